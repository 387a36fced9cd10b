"""The module under threads, forks, Ctrl-C and interpreter shutdown: each case
runs in a child interpreter with a time limit, so that a deadlock fails the
test instead of hanging the suite, and an abort (SIGABRT inside the GL
loader) shows as the child's exit status instead of killing pytest.

The limit, LIMIT seconds, is far above what each child needs (a few 16x9
frames: well under 10 s on the CI machine); a child that reaches it is
hung, not slow."""
import os
import signal
import subprocess
import sys
import textwrap

import shadowlab as sl

LIMIT = 120


def run(code, *, limit=LIMIT):
    """Runs `code` in a fresh interpreter with this one's module path; returns (exit status, stdout, stderr)."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in sys.path if p)
    try:
        done = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], capture_output=True, text=True, timeout=limit, env=env)
    except subprocess.TimeoutExpired as e:
        raise AssertionError(f"hung: no exit within {limit} s\n{e.stdout}\n{e.stderr}")
    return done.returncode, done.stdout, done.stderr


def test_threads_whose_first_calls_make_the_first_arrays():
    # numpy not imported first: four threads' render() calls make the process's first arrays.
    status, out, err = run("""
        import threading, shadowlab as sl
        s = sl.default_scene()
        ts = [threading.Thread(target=lambda: [sl.render(s, 16, 9) for _ in range(3)]) for _ in range(4)]
        [t.start() for t in ts]; [t.join() for t in ts]
        print("done")
    """)
    assert (status, out) == (0, "done\n"), err


def test_bench_in_a_thread_beside_renders():
    # A bench holds the GL lock for its whole run; its checkpoint between frames
    # must not wait for the GIL, which the render threads take and let go of.
    status, out, err = run("""
        import threading, shadowlab as sl
        s = sl.default_scene()
        rows = []
        b = threading.Thread(target=lambda: rows.extend(sl.bench(None, 16, 9, frames=20, warmup=0)))
        ts = [threading.Thread(target=lambda: [sl.render(s, 16, 9) for _ in range(3)]) for _ in range(3)]
        b.start(); [t.start() for t in ts]; b.join(); [t.join() for t in ts]
        print(len(rows))
    """)
    assert (status, out) == (0, "1\n"), err


def test_ctrl_c_stops_a_bench():
    # 100000 frames would take many minutes; SIGINT after the bench began must end it with KeyboardInterrupt.
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in sys.path if p)
    code = textwrap.dedent("""
        import sys, shadowlab as sl
        sl.render(sl.default_scene(), 16, 9)
        print("started", flush=True)
        try:
            sl.bench(None, 16, 9, frames=100000, warmup=0)
        except KeyboardInterrupt:
            print("interrupted"); sys.exit(3)
        print("finished")
    """)
    child = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
                             preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))  # Python installs its handler over SIG_DFL
    try:
        assert child.stdout.readline() == "started\n"
        import time
        time.sleep(2)  # into the bench's frames (a signal before the bench is raised when it starts, which passes too)
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=LIMIT)
    finally:
        child.kill()
    assert (child.returncode, out) == (3, "interrupted\n"), err


def test_a_render_in_an_atexit_handler():
    # Registered before the module: it runs after the module's own atexit hook.
    status, out, err = run("""
        import atexit
        atexit.register(lambda: print(sl.render(sl.default_scene(), 16, 9).shape))
        import shadowlab as sl
        sl.render(sl.default_scene(), 16, 9)
    """)
    assert (status, out) == (0, "(9, 16, 4)\n"), err


def test_renders_after_the_exit_functions_ran_and_in_del_at_shutdown():
    status, out, err = run("""
        import atexit, shadowlab as sl
        class Late:
            def __del__(self):
                print("del", sl.render(sl.default_scene(), 16, 9).shape)
        late = Late()
        sl.render(sl.default_scene(), 16, 9)
        atexit._run_exitfuncs()
        print("after", sl.render(sl.default_scene(), 16, 9).shape)
    """)
    assert status == 0, err
    assert out.startswith("after (9, 16, 4)\n"), out


def test_a_forked_child_raises_runtime_error():
    status, out, err = run("""
        import os, sys, shadowlab as sl
        sl.render(sl.default_scene(), 16, 9)
        pid = os.fork()
        if pid == 0:
            try:
                sl.render(sl.default_scene(), 16, 9)
                print("child drew")
            except RuntimeError as e:
                print("child:", e)
            sys.exit(0)  # a normal exit: the module's atexit hook runs in the child too
        _, child = os.waitpid(pid, 0)
        print("child status", os.waitstatus_to_exitcode(child))
        print("parent", sl.render(sl.default_scene(), 16, 9).shape)
    """)
    assert status == 0, err
    lines = out.splitlines()
    assert lines[0].startswith("child: shadowlab: this process was forked from one that had made its OpenGL context"), out
    assert "'spawn' start method" in lines[0]
    assert lines[1:] == ["child status 0", "parent (9, 16, 4)"], out


def test_spawned_workers_draw(tmp_path):
    # The start method the fork error names: each worker makes its own context.
    script = tmp_path / "workers.py"
    script.write_text(textwrap.dedent("""
        import multiprocessing as mp, shadowlab as sl
        def shape(width):
            return sl.render(sl.default_scene(), width, 9).shape
        if __name__ == "__main__":
            sl.render(sl.default_scene(), 16, 9)
            with mp.get_context("spawn").Pool(2) as pool:
                print(pool.map(shape, [16, 24]))
    """))
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in sys.path if p)
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=LIMIT, env=env)
    assert (done.returncode, done.stdout) == (0, "[(9, 16, 4), (9, 24, 4)]\n"), done.stderr


def test_input_error_is_a_value_error():
    assert issubclass(sl.InputError, ValueError)
