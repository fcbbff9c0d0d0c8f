#!/usr/bin/env python3
"""CPU seconds of a lavapipe render's passes, robust to other work on the machine.

usage: pass_cpu.py SHADER_DIR|- SCENE SAMPLER SPP SIZE [extra wavelit-cli render args...]
Runs `wavelit-cli render` on the Vulkan device with LP_NUM_THREADS=2 and polls /proc for the CPU
time of each of its threads. Lavapipe runs the passes on its two worker threads and the compile,
tables and upload on the main thread, so the workers' CPU seconds are the passes' cost even when
other builds share the cores (wall time is not). Prints: worker_cpu_s main_cpu_s wall_s.
With env DEVICE=cpu it renders on the C++ tracer instead (its tile threads live one pass each, so
they are counted through the process's rusage) and prints SPP x (T(SPP) - T(1)) / (SPP - 1), T the
whole process's CPU seconds: the passes without the BVH and tables, which the Vulkan figure leaves
on the main thread too; a `wavelet` cache's build in the first pass is left out with them (none
where every material is env-mis). Then 0 and the wall of the SPP render.
SHADER_DIR (not -) is passed as WAVELIT_SHADER_DIR to compare shader variants with one binary;
env CLI picks the binary (default build/release/renderer/cli/wavelit-cli). The first run of a new
shader variant includes lavapipe's LLVM compile on the worker threads: discard it."""
import os, sys, subprocess, time, glob, resource
shader, scene, sampler, spp, size = sys.argv[1:6]
extra = sys.argv[6:]
cli = os.environ.get("CLI", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "release", "renderer", "cli", "wavelit-cli"))
env = dict(os.environ, LP_NUM_THREADS="2")
if shader != "-": env["WAVELIT_SHADER_DIR"] = shader
out = f"/tmp/pass_cpu_{os.getpid()}.exr"
cmd = [cli, "render", scene, "-o", out, "--sampler", sampler, "--spp", spp, "--width", size,
       "--height", size, "--device", os.environ.get("DEVICE", "vulkan")] + extra
tck = os.sysconf("SC_CLK_TCK")
t0 = time.time()
def process_cpu(command):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if r.returncode != 0:
        print(r.stdout.decode()); sys.exit(1)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
if os.environ.get("DEVICE", "vulkan") == "cpu":
    n = int(spp)
    if n < 2: sys.exit("pass_cpu.py: DEVICE=cpu needs SPP >= 2")
    one = process_cpu([("1" if a == spp and cmd[i - 1] == "--spp" else a) for i, a in enumerate(cmd)])
    t0 = time.time()
    total = process_cpu(cmd)
    print(f"{n * (total - one) / (n - 1):.2f} 0.00 {time.time() - t0:.2f}")
    os.remove(out)
    sys.exit(0)
p = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
threads = {}
main_tid = str(p.pid)
while p.poll() is None:
    for d in glob.glob(f"/proc/{p.pid}/task/*"):
        try:
            f = open(d + "/stat").read()
            parts = f[f.rfind(")") + 2:].split()
            threads[os.path.basename(d)] = (int(parts[11]) + int(parts[12])) / tck
        except Exception:
            pass
    time.sleep(0.05)
wall = time.time() - t0
o = p.stdout.read().decode()
if p.returncode != 0:
    print(o); sys.exit(1)
main = threads.pop(main_tid, 0.0)
# lavapipe's workers are the threads that burned the most CPU besides main
work = sorted(threads.values(), reverse=True)
print(f"{sum(work[:2]):.2f} {main:.2f} {wall:.2f}")
os.remove(out)
