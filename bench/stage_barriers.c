// The same CPU work done by two threads pinned to CPUs 0 and 1, either without a pause
// ("steady": each thread runs its half straight through, as Cycles' render threads do) or in
// stages with a barrier between them ("stages": the threads take chunks of a stage from a
// shared counter, the last to finish wakes the host thread, which starts the next stage; a
// thread with no chunk left sleeps on a condition variable until then, as PoCL's pthread
// workers do at the end of each command). With SPIN_US, a thread with no chunk left first
// polls for the next stage for up to that many microseconds before it sleeps. Prints the wall
// seconds. bench/barriers.py runs it quiet and beside a niced load (bench/threads.md).
//
//   stage_barriers steady|stages STAGES CHUNKS_PER_STAGE [SPIN_US]
#define _GNU_SOURCE
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { ChunkIterations = 10000, Threads = 2 };

static double now(void) {
  struct timespec T;
  clock_gettime(CLOCK_MONOTONIC, &T);
  return T.tv_sec + T.tv_nsec * 1e-9;
}

static void pin(int Cpu) {
  cpu_set_t S;
  CPU_ZERO(&S);
  CPU_SET(Cpu, &S);
  pthread_setaffinity_np(pthread_self(), sizeof S, &S);
}

static volatile double Sink;
static void work(long Chunks) { // a dependent chain: no memory traffic, no vectorisation
  double X = 1.0;
  for (long I = 0; I < Chunks * ChunkIterations; ++I)
    X = X * 1.0000001 + 1e-9;
  Sink = X;
}

static long Stages, PerStage, SpinUs;
static pthread_mutex_t Lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t StageStart = PTHREAD_COND_INITIALIZER, StageDone = PTHREAD_COND_INITIALIZER;
static atomic_long Generation; // the stage running (written under Lock); -1: quit
static int Finished;    // threads done with it (under Lock)
static atomic_long Next;

static void *stageWorker(void *Arg) {
  pin((int)(long)Arg);
  long Seen = 0;
  for (;;) {
    for (const double End = now() + SpinUs * 1e-6; SpinUs && now() < End;)
      if (atomic_load(&Generation) != Seen)
        break;
    pthread_mutex_lock(&Lock);
    while (Generation == Seen)
      pthread_cond_wait(&StageStart, &Lock);
    Seen = Generation;
    pthread_mutex_unlock(&Lock);
    if (Seen < 0)
      return NULL;
    while (atomic_fetch_add(&Next, 1) < PerStage)
      work(1);
    pthread_mutex_lock(&Lock);
    if (++Finished == Threads)
      pthread_cond_signal(&StageDone);
    pthread_mutex_unlock(&Lock);
  }
}

static void *steadyWorker(void *Arg) {
  pin((int)(long)Arg);
  work(Stages * PerStage / Threads);
  return NULL;
}

int main(int Argc, char **Argv) {
  if ((Argc != 4 && Argc != 5) || (strcmp(Argv[1], "steady") && strcmp(Argv[1], "stages"))) {
    fprintf(stderr, "usage: stage_barriers steady|stages STAGES CHUNKS_PER_STAGE [SPIN_US]\n");
    return 2;
  }
  const int Steady = !strcmp(Argv[1], "steady");
  Stages = atol(Argv[2]), PerStage = atol(Argv[3]), SpinUs = Argc == 5 ? atol(Argv[4]) : 0;
  pthread_t T[Threads];
  const double T0 = now();
  for (long I = 0; I < Threads; ++I)
    pthread_create(&T[I], NULL, Steady ? steadyWorker : stageWorker, (void *)I);
  for (long S = 1; !Steady && S <= Stages; ++S) {
    pthread_mutex_lock(&Lock);
    atomic_store(&Next, 0);
    Finished = 0;
    Generation = S;
    pthread_cond_broadcast(&StageStart);
    while (Finished < Threads)
      pthread_cond_wait(&StageDone, &Lock);
    pthread_mutex_unlock(&Lock);
  }
  if (!Steady) {
    pthread_mutex_lock(&Lock);
    Generation = -1;
    pthread_cond_broadcast(&StageStart);
    pthread_mutex_unlock(&Lock);
  }
  for (int I = 0; I < Threads; ++I)
    pthread_join(T[I], NULL);
  printf("%.4f\n", now() - T0);
  return 0;
}
