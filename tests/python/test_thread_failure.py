"""Worker threads the system refuses (issue 36): tritri.arrange (both paths), tritri.boolean
and tritri.csg start their threads before any work (CallWorkers, python/module_common.h) and
raise tritri.ThreadError (a RuntimeError), "cannot start N worker threads: ...", instead of
oneTBB ending the interpreter with SIGABRT from a worker. Each call runs in a child
interpreter under an address-space limit (RLIMIT_AS, set in the child only): 2 GB holds the
interpreter, numpy and a 2-thread run, but not 1023 stacks of oneTBB's 4 MB. The child
prints a marker when it caught the exception, then shows that the same process still
arranges with 2 threads."""

import subprocess
import sys
import textwrap

import numpy as np
import pytest

import tritri

LIMIT = 2 << 30  # bytes of address space in the child
resource = pytest.importorskip("resource")

CHILD = textwrap.dedent("""
    import atexit
    import os
    import shutil
    import sys
    import tempfile
    from fractions import Fraction
    import numpy as np
    import tritri

    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    F = np.array([[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]])
    call = sys.argv[1]

    def run(threads):
        if call == "arrange":
            return tritri.arrange(V, F, threads=threads)
        if call == "arrange_exact":
            Vx = V.astype(object) + Fraction(1, 3)  # not float64: the exact pipeline
            return tritri.arrange(Vx, F, threads=threads)
        if call == "boolean":
            return tritri.boolean([(V, F), (V + 0.25, F)], op="union", threads=threads)
        if call == "csg":
            folder = tempfile.mkdtemp()
            atexit.register(shutil.rmtree, folder)
            with open(os.path.join(folder, "a.off"), "w") as f:
                f.write("OFF\\n4 4 0\\n" + "".join(f"{x} {y} {z}\\n" for x, y, z in V) +
                        "".join(f"3 {i} {j} {k}\\n" for i, j, k in F))
            scene = os.path.join(folder, "scene.csg")
            with open(scene, "w") as f:
                f.write('union() { import("a.off"); '
                        'multmatrix([[1,0,0,0.25],[0,1,0,0.25],[0,0,1,0.25],[0,0,0,1]]) import("a.off"); }')
            return tritri.csg(scene, threads=threads)
        raise SystemExit("unknown call " + call)

    try:
        run(int(sys.argv[2]))
        print("NO-ERROR")
    except tritri.ThreadError as e:
        assert isinstance(e, RuntimeError)
        print("CAUGHT-THREAD-ERROR", e)
    print("AFTER", len(run(2)["F"]))
""")


def run_child(call, threads, limit):
    def set_limit():
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    return subprocess.run([sys.executable, "-c", CHILD, call, str(threads)], capture_output=True, text=True,
                          timeout=120, preexec_fn=set_limit if limit else None)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS caps thread stacks on Linux")
@pytest.mark.parametrize("call", ["arrange", "arrange_exact", "boolean", "csg"])
def test_refused_threads_raise_thread_error(call):
    r = run_child(call, tritri.MAX_THREADS, LIMIT)
    assert r.returncode == 0, f"child ended with {r.returncode} (negative: a signal)\n{r.stdout}\n{r.stderr}"
    assert "CAUGHT-THREAD-ERROR" in r.stdout, r.stdout + r.stderr
    assert f"cannot start {tritri.MAX_THREADS} worker threads" in r.stdout, r.stdout
    assert "AFTER " in r.stdout, r.stdout + r.stderr  # the process still works with fewer threads


@pytest.mark.parametrize("call", ["arrange", "arrange_exact", "boolean", "csg"])
def test_two_threads_without_limit(call):
    r = run_child(call, 2, None)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "NO-ERROR" in r.stdout and "AFTER " in r.stdout, r.stdout + r.stderr


def test_thread_error_is_a_runtime_error():
    assert issubclass(tritri.ThreadError, RuntimeError)
    assert "ThreadError" in tritri.__all__


def test_two_threads_in_process():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    F = np.array([[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]])
    assert len(tritri.arrange(V, F, threads=2)["F"]) == 4
