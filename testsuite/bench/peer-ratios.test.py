import os
import subprocess
import sys

from texcc_tools.bench import accuracy

points = []
for renderer, (fixed, per, k) in {"texrender-sobol": (1.0, 0.01, 0.09),
                                  "cycles": (0.2, 0.02, 0.1)}.items():
    for spp in (1, 4, 16, 64):
        for rep in range(3):
            points.append({"renderer": renderer, "spp": spp, "rmse": k / spp ** 0.5,
                           "cpuTotal": fixed + per * spp})
r = accuracy.peer_ratios(points, boot=20)
m = r["timeModel"]
print("model texrender %.4f + %.4f spp, cycles %.4f + %.4f spp" % tuple(
    m["texrender-sobol"] + m["cycles"]))
for spp in ("4", "64"):
    print("spp %s: %s" % (spp, " ".join(
        "%s %s" % (k, "None" if v["ratio"] is None else "%.4f" % v["ratio"])
        for k, v in r[spp].items())))
print("interval %.4f %.4f" % tuple(r["4"]["equalSpp"]["ci95"]))

SPIN = ("import sys, time\n"
        "while time.process_time() < 0.3: pass\n"
        "sys.stdout.write('spun\\n'); sys.stdout.flush(); sys.stdin.read()\n")
before = accuracy.children_cpu()
p = subprocess.Popen([sys.executable, "-c", SPIN], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                     text=True)
p.stdout.readline()
live = accuracy.process_cpu(p.pid)
print("live child cpu", "ok" if live >= 0.25 else "wrong: %s" % live)
p.stdin.close()
p.wait()
done = accuracy.children_cpu() - before
print("finished child cpu", "ok" if done >= 0.25 else "wrong: %s" % done)
