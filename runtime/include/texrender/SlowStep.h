#ifndef TEXRENDER_SLOWSTEP_H
#define TEXRENDER_SLOWSTEP_H
// Says on stderr what texrender is waiting for when it takes a while (issue 36): a step that has
// run for a second prints "texrender: building the texture kernel: 1 s ...", again every 2 s
// while it runs, and "texrender: building the texture kernel: done in 4.2 s" when it ends.
// Steps that end sooner print nothing. $TEXRENDER_ANNOUNCE_AFTER (seconds, default 1) sets the
// threshold; 0 announces every step at once, which is how the tests see the lines without
// waiting for a slow build. texrender prints them on a terminal, with --progress and in --watch
// sessions, never with --quiet (setSlowStepAnnouncements).

#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace texrender {

/// Off by default (a library user prints nothing); texrender turns it on (above).
void setSlowStepAnnouncements(bool On);

class SlowStep {
public:
  explicit SlowStep(std::string What);
  ~SlowStep();
  SlowStep(const SlowStep &) = delete;
  SlowStep &operator=(const SlowStep &) = delete;

private:
  void watch();
  std::string What;
  double Start;
  bool Announced = false;
  bool Done = false;
  std::mutex M;
  std::condition_variable Wake;
  std::thread Thread;
};

} // namespace texrender

#endif
