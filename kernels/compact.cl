/* compact.cl: active-path compaction between bounces: the paths still alive are appended to
 * the next active list (order does not matter: every path owns its random stream). */
#include "rt_types.h"

__kernel void compact(__global const RtPath *paths, __global const int *active, int numActive,
                      __global int *nextActive, __global int *counter) {
  int i = get_global_id(0);
  if (i >= numActive)
    return;
  int pid = active[i];
  if (paths[pid].flags & RT_PATH_ALIVE)
    nextActive[atomic_inc(counter)] = pid;
}
