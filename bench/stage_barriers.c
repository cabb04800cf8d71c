// The same CPU work done by two threads pinned to CPUs 0 and 1, either without a pause
// ("steady": each thread runs its half straight through, as Cycles' render threads do) or in
// stages with a barrier between them ("stages": the threads take chunks of a stage from a
// shared counter, the last to finish wakes the host thread, which starts the next stage; a
// thread with no chunk left sleeps on a condition variable until then, as PoCL's pthread
// workers do at the end of each command). With SPIN_US, a thread with no chunk left first
// polls for the next stage for up to that many microseconds before it sleeps. "halves" splits
// every stage into two independent halves (two chains of STAGES stages of CHUNKS_PER_STAGE / 2
// chunks, as two halves of a pass's paths would be): a thread takes a chunk of either chain's
// current stage, and a chain's next stage starts when its current one is done, so a thread
// waits only when both chains wait. Prints the wall seconds. bench/barriers.py runs it quiet
// and beside a niced load (bench/threads.md).
//
//   stage_barriers steady|stages|halves STAGES CHUNKS_PER_STAGE [SPIN_US]
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

typedef struct {
  long Stage;             // the current stage, 0..Stages (done)
  long Dealt, Done;       // chunks of it handed out, finished
} Chain;
static Chain Chains[2]; // under Lock

/// A chunk of either chain's current stage (Chain index), or -1 with Lock held to wait; -2 when
/// both chains are done.
static int takeChunk(int Prefer) {
  for (int K = 0; K < 2; ++K) {
    Chain *C = &Chains[(Prefer + K) % 2];
    if (C->Stage < Stages && C->Dealt < PerStage / 2) {
      ++C->Dealt;
      return (Prefer + K) % 2;
    }
  }
  return Chains[0].Stage == Stages && Chains[1].Stage == Stages ? -2 : -1;
}

static void *halvesWorker(void *Arg) {
  const int Me = (int)(long)Arg;
  pin(Me);
  pthread_mutex_lock(&Lock);
  for (;;) {
    const int C = takeChunk(Me);
    if (C == -2)
      break;
    if (C == -1) {
      pthread_cond_wait(&StageStart, &Lock);
      continue;
    }
    pthread_mutex_unlock(&Lock);
    work(1);
    pthread_mutex_lock(&Lock);
    if (++Chains[C].Done == PerStage / 2) { // the chain's stage is done: its next one starts
      ++Chains[C].Stage;
      Chains[C].Dealt = Chains[C].Done = 0;
      pthread_cond_broadcast(&StageStart);
    }
  }
  pthread_mutex_unlock(&Lock);
  return NULL;
}

static void *steadyWorker(void *Arg) {
  pin((int)(long)Arg);
  work(Stages * PerStage / Threads);
  return NULL;
}

int main(int Argc, char **Argv) {
  if ((Argc != 4 && Argc != 5) ||
      (strcmp(Argv[1], "steady") && strcmp(Argv[1], "stages") && strcmp(Argv[1], "halves"))) {
    fprintf(stderr, "usage: stage_barriers steady|stages|halves STAGES CHUNKS_PER_STAGE [SPIN_US]\n");
    return 2;
  }
  const int Steady = !strcmp(Argv[1], "steady"), Halves = !strcmp(Argv[1], "halves");
  Stages = atol(Argv[2]), PerStage = atol(Argv[3]), SpinUs = Argc == 5 ? atol(Argv[4]) : 0;
  pthread_t T[Threads];
  const double T0 = now();
  for (long I = 0; I < Threads; ++I)
    pthread_create(&T[I], NULL, Steady ? steadyWorker : Halves ? halvesWorker : stageWorker,
                   (void *)I);
  for (long S = 1; !Steady && !Halves && S <= Stages; ++S) {
    pthread_mutex_lock(&Lock);
    atomic_store(&Next, 0);
    Finished = 0;
    Generation = S;
    pthread_cond_broadcast(&StageStart);
    while (Finished < Threads)
      pthread_cond_wait(&StageDone, &Lock);
    pthread_mutex_unlock(&Lock);
  }
  if (!Steady && !Halves) {
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
