#!/usr/bin/python3
"""`--threads N` is the whole process's thread count: `mrsim run --threads N` never runs more
than N threads at once. VTK's own SMP pool (TBB in Debian's build) ignores --threads and adds one
worker per core to VTK's loops (an array's range, which VTK's XML writers take of every array;
mrsim's own piece writer, io/vtk_xml_piece.hpp, leaves to them only blocks it cannot write as they
do); main.cpp makes VTK's loops sequential unless the user chose a backend
(VTK_SMP_BACKEND_IN_USE). The run's threads are sampled from /proc/<pid>/task while liver_probe
(four levels, every frame written) runs.

Control: the same sampling, on a process that takes a large array's range through VTK with
VTK_SMP_BACKEND_IN_USE=TBB, must see more than one thread, so that the sampler is shown able to
see VTK's pool; the control is left out when this VTK has no TBB backend or the machine one
core."""
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: check, parse_args, report)

check = cli.check


# Ranges of a 20-million-value array, taken again and again: VTK's loop over its values, run by
# the SMP backend in use.
VTK_RANGES = """
from vtkmodules.vtkCommonCore import vtkDoubleArray
a = vtkDoubleArray()
a.SetNumberOfTuples(20000000)
a.Fill(1.5)
for _ in range(20):
    a.Modified()
    a.GetRange()
"""


def most_threads(binary, scenario, out, threads, backend=None):
    """Exit code and the largest number of threads seen in the run (sampled every ~1 ms)."""
    return most_threads_of([binary, "run", scenario, "-o", out, "-q", "--threads", str(threads),
                            "--set", "time.duration=0.3"], backend)


def most_threads_of(command, backend=None):
    env = dict(os.environ)
    env.pop("VTK_SMP_BACKEND_IN_USE", None)
    if backend is not None:
        env["VTK_SMP_BACKEND_IN_USE"] = backend
    proc = subprocess.Popen(command, env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    most = 0
    tasks = "/proc/%d/task" % proc.pid
    while proc.poll() is None:
        try:
            most = max(most, len(os.listdir(tasks)))
        except OSError:  # the process ended between poll and listdir
            break
        time.sleep(0.001)
    return proc.wait(timeout=600), most


def tbb_available():
    """Whether this VTK (the one python3-vtk9 and mrsim both load) has a TBB backend."""
    from vtkmodules.vtkCommonCore import vtkSMPTools
    return bool(vtkSMPTools.SetBackend("TBB"))


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    if not os.path.isdir("/proc/self/task"):
        print("skipped: no /proc/<pid>/task to count threads")
        return 77
    scenario = os.path.join(args.source, "scenarios", "liver_probe.yaml")
    cores = os.cpu_count() or 1
    with tempfile.TemporaryDirectory() as tmp:
        for threads in sorted({1, min(2, cores)}):
            rc, most = most_threads(args.binary, scenario, os.path.join(tmp, "t%d" % threads),
                                    threads)
            check(rc == 0 and 1 <= most <= threads,
                  "--threads %d: exit %d, at most %d threads at once (seen %d)"
                  % (threads, rc, threads, most))
        if cores >= 2 and tbb_available():  # one core: TBB starts no worker to see
            rc, most = most_threads_of(["/usr/bin/python3", "-c", VTK_RANGES], "TBB")
            check(rc == 0 and most > 1,
                  "control: VTK's ranges with VTK_SMP_BACKEND_IN_USE=TBB are seen running %d "
                  "threads (the sampler sees VTK's pool)" % most)
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
