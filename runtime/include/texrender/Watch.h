#ifndef TEXRENDER_WATCH_H
#define TEXRENDER_WATCH_H

// texrender --watch (docs/live.md): renders progressively into one image while it watches
// scene.json, graph.json and every source file the graph names; a saved change is applied the
// cheapest way (argument values: the live editor's upload; anything else in the graph or a
// source file: texcc on a background thread while the current kernel keeps rendering; the
// scene: a reload), and accumulation restarts.

#include "texrender/Layout.h"
#include "texrender/LiveEdit.h"
#include "texrender/Renderer.h"
#include "texrender/Scene.h"

#include <atomic>
#include <functional>
#include <istream>
#include <optional>
#include <string>
#include <sys/stat.h>
#include <vector>

#include <nlohmann/json.hpp>

namespace texrender {

/// Files watched by polling their modification time and size (every ~100 ms, the caller's
/// loop). Polling rather than inotify: editors save by writing in place or by renaming a new
/// file over the old one (which an inotify watch on the file loses), a handful of stat() calls
/// cost microseconds, and it runs unchanged off Linux.
class FileWatcher {
public:
  void watch(const std::vector<std::string> &Paths);
  /// The watched files whose time or size changed since the last call (or that appeared or
  /// vanished).
  std::vector<std::string> changed();

private:
  struct Seen {
    std::string Path;
    bool Exists = false;
    long long Size = 0, MTimeNs = 0;
  };
  static Seen look(const std::string &Path);
  std::vector<Seen> Files;
};

/// The files a graph depends on: the graph and its sources (resolved against its folder).
std::vector<std::string> graphFiles(const std::string &GraphPath,
                                    const std::vector<std::string> &Sources);

/// The longest line --interactive and --watch --control read; a longer one ends the session.
constexpr size_t MaxEditLine = 64 * 1024;

enum class LineRead { Line, End, TooLong };

/// Reads one line (without its newline) of at most Max bytes, so that an endless line
/// (/dev/zero) neither hangs the session nor fills memory.
LineRead readBoundedLine(std::istream &In, std::string &Line, size_t Max);

struct WatchOptions {
  std::string ScenePath, Output;
  int Width = 0, Height = 0; // the image written (the region's size with --region)
  /// Loads scene.json with the command line's overrides (--spp, --size, ...).
  std::function<Scene()> LoadScene;
  RendererOptions Renderer;
  const std::atomic<int> *Stop = nullptr; // a signal asked to stop (0: none)
  /// --control: edit commands ("ID EDIT", "quit") on standard input, one JSON event a line on
  /// standard output (docs/live.md, "Control channel"); the session also ends at the end of
  /// standard input.
  bool Control = false;
  /// The first image after a change is one sample per pixel at 1/F of the width and height,
  /// F = 2, 4, 8 or 16: the smallest whose predicted pass time fits FirstPassBudget (PassTimes,
  /// from the passes rendered so far), as viewports do; then accumulation restarts at full
  /// resolution (the refined image equals a batch render bit for bit). With Control the
  /// reduced image is written at its own size (the front end scales it up), else each of its
  /// pixels is drawn FxF.
  bool ReducedFirstPass = true;
  double FirstPassBudget = 0.060; // seconds
};

/// Predicts a pass's time from its pixel count: the passes rendered so far, one smoothed time
/// per pass size (the 4 sizes seen last; each new time weighs 1/2), fitted with a line (fixed
/// cost + cost per pixel; through the origin while one size is known).
class PassTimes {
public:
  void record(double Pixels, double Seconds);
  /// Seconds predicted for a pass of Pixels; negative: nothing recorded yet.
  double predict(double Pixels) const;
  /// The reduction factor (2, 4, 8, 16) of a Width x Height image: the smallest whose pass
  /// (ceil(Width/F) x ceil(Height/F) pixels) is predicted to take at most Budget seconds; the
  /// largest (down to 1 pixel a side) when none is; 2 when nothing is recorded.
  int factor(int Width, int Height, double Budget) const;

private:
  struct Size {
    double Pixels = 0, Seconds = 0;
    unsigned Seq = 0;
  };
  std::vector<Size> Sizes;
  unsigned Seq = 0;
};

struct WatchResult {
  unsigned Frames = 0; // frames rendered with all their samples
  bool Ok = true;      // false: the control session ended on an over-long line
};

/// Runs the watch session until *Stop (or, with Control, 'quit' or the end of standard input).
/// Messages (one a line, "texrender: watch: ...") on stderr; errors in the user's files are
/// printed and the last good state keeps rendering.
WatchResult runWatch(WatchOptions O, const Layout &Initial);

} // namespace texrender

#endif
