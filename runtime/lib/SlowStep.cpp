#include "texrender/SlowStep.h"
#include "texrender/TextureTiers.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace texrender {

namespace {
std::atomic<bool> Enabled{false};

/// $TEXRENDER_ANNOUNCE_AFTER, else 1 s.
double threshold() {
  if (const char *E = std::getenv("TEXRENDER_ANNOUNCE_AFTER"); E && *E) {
    char *End = nullptr;
    const double V = std::strtod(E, &End);
    if (End && !*End && std::isfinite(V) && V >= 0)
      return V;
  }
  return 1.0;
}
} // namespace

void setSlowStepAnnouncements(bool On) { Enabled.store(On); }

SlowStep::SlowStep(std::string WhatIn) : What(std::move(WhatIn)), Start(steadySeconds()) {
  if (!Enabled.load())
    return;
  if (threshold() <= 0) { // every step, at once (the tests): no race with a quick step's end
    std::fprintf(stderr, "texrender: %s: 0 s ...\n", What.c_str());
    std::fflush(stderr);
    Announced = true;
  }
  Thread = std::thread([this] { watch(); });
}

SlowStep::~SlowStep() {
  if (!Thread.joinable())
    return;
  {
    std::lock_guard<std::mutex> Lock(M);
    Done = true;
  }
  Wake.notify_all();
  Thread.join();
  if (Announced)
    std::fprintf(stderr, "texrender: %s: done in %.1f s\n", What.c_str(), steadySeconds() - Start);
}

void SlowStep::watch() {
  std::unique_lock<std::mutex> Lock(M);
  double Next = Announced ? 2.0 : threshold();
  for (;;) {
    const double Left = Start + Next - steadySeconds();
    if (Wake.wait_for(Lock, std::chrono::duration<double>(std::max(Left, 0.0)),
                      [this] { return Done; }))
      return;
    if (steadySeconds() < Start + Next)
      continue;
    std::fprintf(stderr, "texrender: %s: %.0f s ...\n", What.c_str(),
                 std::floor(steadySeconds() - Start));
    std::fflush(stderr);
    Announced = true;
    Next = std::floor(Next) + 2.0;
  }
}

} // namespace texrender
