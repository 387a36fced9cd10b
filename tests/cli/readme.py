"""Every `shadowlab` command README.md shows runs as written, at a small
size: the command lines are taken from README.md itself (code blocks and
table cells starting with ./build/apps/shadowlab/shadowlab), the tool's
path replaced by the built one, --width/--height replaced by 64x36 (the viewer 320x240)
(bench: also --frames 1 --warmup 0), run from a scratch directory where
`scenes` is the repository's. A command that fails or writes nothing it
said it would fails the test. `view` needs a display: it is run with two
frames under xvfb-run when that exists (tests/cli/view.sh tests the viewer
itself) and skipped, saying why, when not. Setup commands (scripts/*.sh)
are CI's.

    python3 readme.py TOOL SOURCE_DIR
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

PREFIX = "./build/apps/shadowlab/shadowlab"
SIZED = {"render", "compare", "bench", "view"}


def commands(readme):
    found = []
    in_block = False
    for line in readme.splitlines():
        if line.startswith("```"):
            in_block = not in_block
            continue
        if in_block and line.startswith(PREFIX + " "):
            found.append(line.split("  #", 1)[0].strip())
        elif not in_block:
            found += [m.group(1) for m in re.finditer(r"`(" + re.escape(PREFIX) + r" [^`]*)`", line)]
    return found


def small(args):
    """args (after the tool) at 64x36; bench with one timed frame."""
    out, skip = [], False
    drop = {"--width", "--height"} | ({"--frames", "--warmup", "--rounds"} if args[0] == "bench" else set())
    for a in args:
        if skip:
            skip = False
            continue
        if a in drop:
            skip = True
            continue
        out.append(a)
    if args[0] in SIZED:  # the viewer's window is at least 64 pixels high
        out += ["--width", "64", "--height", "36"] if args[0] != "view" else ["--width", "320", "--height", "240"]
    if args[0] == "bench":
        out += ["--frames", "1", "--warmup", "0"]
    return out


def main():
    tool, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    with open(os.path.join(source, "README.md")) as f:
        lines = commands(f.read())
    assert len(lines) >= 10, f"found only {len(lines)} shadowlab commands in README.md"
    failed = 0
    with tempfile.TemporaryDirectory() as work:
        os.symlink(os.path.join(source, "scenes"), os.path.join(work, "scenes"))
        for line in lines:
            args = small(shlex.split(line)[1:])
            run = [tool] + args
            if args[0] == "view":
                xvfb = shutil.which("xvfb-run")
                if not xvfb:
                    print(f"skipped (no display and no xvfb-run): {line}")
                    continue
                run = [xvfb, "-a", tool] + args + ["--frames", "2"]
            done = subprocess.run(run, cwd=work, capture_output=True, text=True, timeout=600)
            if done.returncode != 0:
                failed += 1
                print(f"FAIL ({done.returncode}): {line}\n  ran: {shlex.join(run)}\n  {done.stderr.strip()}")
                continue
            # What render and compare say they wrote is there.
            for path in re.findall(r"[^\s<>]+\.(?:png|json)\b", done.stdout):
                if not os.path.isabs(path) and not os.path.exists(os.path.join(work, path)):
                    failed += 1
                    print(f"FAIL: {line}: said it wrote {path}, which is not there")
            print(f"ok: {line}")
    print(f"{len(lines) - failed} of {len(lines)} README commands ran")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
