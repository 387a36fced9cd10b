#!/usr/bin/python3
"""Hostile-input battery for shadowlab (CLI, viewer, Python module).

Every input a user can give must end in ONE line of error naming the option
and where its value came from (CLI: `shadowlab: error: ...` on stderr;
Python: ValueError/RuntimeError), a non-zero exit, no crash, nothing left
behind, bounded time and memory; valid inputs must exit 0.

Usage:
  /usr/bin/python3 tests/hostile/run.py [--snapshot DIR] [--only REGEX] [--jobs 2] [--list]

--snapshot DIR holds bin/shadowlab, bin/libshadowlab.so*, python/ and scenes/
(scripts/hostile.sh makes one from the build; default $SHADOWLAB_SNAPSHOT). Writes DIR/results.jsonl and
DIR/report.md; work files go to DIR/hostile-work/ (each case in its own
directory, kept for repros). Only the standard library is used.
"""
import argparse
import base64
import concurrent.futures
import json
import os
import re
import shlex
import shutil
import signal
import struct
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
from cases import build_cases  # noqa: E402
from judgement import EXPECTATION_FIXES, JUDGEMENT  # noqa: E402

MEMORY_LIMIT_MB = 6000  # an input that makes the tool hold more than this is "unbounded memory"
PROGRESS = re.compile(r"^\[[#.]*\] |^bench: \d+ runs?$")
TEMP_NAME = re.compile(r"\.(pending|partial|previous)-\d+")
CRASH_TEXT = re.compile(r"terminate called|Aborted|Segmentation fault|what\(\):|core dumped|AddressSanitizer|Traceback")


def snapshot_tree(root):
    seen = set()
    if not os.path.lexists(root):
        return seen
    for dirpath, dirnames, filenames in os.walk(root, followlinks=False):
        for n in dirnames + filenames:
            seen.add(os.path.relpath(os.path.join(dirpath, n), root))
    return seen


def rss_kb(pid):
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except OSError:
        pass
    return 0


def run_process(argv, cwd, env, timeout, stdout_path, stderr_path, fsize=None, aslimit=None):
    """Runs argv; returns (rc, seconds, max_rss_mb, killed_reason)."""
    def limit():
        import resource
        if fsize:
            resource.setrlimit(resource.RLIMIT_FSIZE, (fsize, fsize))
        if aslimit:
            resource.setrlimit(resource.RLIMIT_AS, (aslimit, aslimit))
    with open(stdout_path, "wb") as out, open(stderr_path, "wb") as err:
        start = time.monotonic()
        p = subprocess.Popen(argv, cwd=cwd, env=env, stdout=out, stderr=err, stdin=subprocess.DEVNULL, start_new_session=True,
                             preexec_fn=limit if (fsize or aslimit) else None)
        peak = 0
        killed = None
        while True:
            rc = p.poll()
            if rc is not None:
                break
            peak = max(peak, rss_kb(p.pid))
            if peak > MEMORY_LIMIT_MB * 1024:
                killed = "memory"
            elif time.monotonic() - start > timeout:
                killed = "timeout"
            if killed:
                try:
                    os.killpg(p.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                rc = p.wait()
                break
            time.sleep(0.02)
        secs = time.monotonic() - start
    return rc, secs, peak / 1024.0, killed


def nonempty_lines(text, progress):
    lines = [l for l in text.splitlines() if l.strip()]
    if progress:
        lines = [l for l in lines if not PROGRESS.search(l)]
    return lines


def classify(c, rc, killed, stdout, stderr, new_paths, temp_left, absent_violations):
    """Returns (verdict, reason)."""
    problems = []
    if killed == "timeout":
        return "not-clean", f"unbounded time: killed after {c['timeout']} s"
    if killed == "memory":
        return "not-clean", f"unbounded memory: over {MEMORY_LIMIT_MB} MB resident, killed"
    if rc < 0 or rc >= 128:
        problems.append(f"crash: exit {rc} (signal {-rc if rc < 0 else rc - 128})")
    if CRASH_TEXT.search(stderr) and c["tool"] != "py":
        problems.append("crash text on stderr")
    if temp_left:
        problems.append("temporary files left: " + ", ".join(sorted(temp_left))[:200])
    expect = c["expect"]
    if c["tool"] == "py":
        res = None
        for line in stdout.splitlines():
            if line.startswith("@@RESULT@@ "):
                res = json.loads(line[len("@@RESULT@@ "):])
        if res is None:
            problems.append("no result from the Python driver (died?)")
            return "not-clean", "; ".join(problems)
        err_lines = nonempty_lines(stderr, False)
        if err_lines:
            problems.append("stderr output: " + err_lines[0][:120])
        if res["ok"]:
            if expect == "error":
                problems.append("accepted: no exception")
            if new_paths and expect == "error":
                problems.append("wrote: " + ", ".join(sorted(new_paths))[:200])
        else:
            msg = res["msg"]
            if expect == "ok":
                problems.append(f"valid input refused: {res['exc']}: {msg[:200]}")
            else:
                # TypeError for an argument of the wrong Python type is accepted as the exception's type (the message must still be one line naming it)
                if res["exc"] not in ["ValueError", "RuntimeError", "TypeError"] + c.get("exc_ok", []):
                    problems.append(f"{res['exc']} instead of ValueError/RuntimeError")
                if "\n" in msg:
                    problems.append(f"message of {msg.count(chr(10)) + 1} lines")
                missing = [n for n in c["names"] if n not in msg]
                if missing:
                    problems.append("does not name " + " / ".join(repr(m) for m in missing))
                if len(msg) > 2000:
                    problems.append(f"message of {len(msg)} characters")
            if new_paths:
                problems.append("left behind: " + ", ".join(sorted(new_paths))[:200])
        return ("clean" if not problems else "not-clean"), "; ".join(problems) or ("accepted" if res["ok"] else "refused cleanly")
    lines = nonempty_lines(stderr, c.get("progress", False))
    if rc == 0:
        if expect == "error":
            problems.append("accepted: exit 0")
            if new_paths:
                problems.append("wrote: " + ", ".join(sorted(new_paths))[:200])
        for o in c.get("outputs", []):
            if not os.path.exists(os.path.join(c["dir"], o)):
                problems.append(f"exit 0 but {o} not written")
        if absent_violations and expect == "error":
            problems.append("left behind: " + ", ".join(absent_violations))
        return ("clean" if not problems else "not-clean"), "; ".join(problems) or "accepted"
    # non-zero exit
    if expect == "ok":
        problems.append("valid input refused: " + (lines[0][:200] if lines else "(no message)"))
        return "not-clean", "; ".join(problems)
    if len(lines) != 1:
        problems.append(f"{len(lines)} non-empty stderr lines")
    errs = [l for l in lines if l.startswith("shadowlab: error: ")]
    if not errs:
        problems.append("no 'shadowlab: error:' line")
    msg = errs[0] if errs else (lines[0] if lines else "")
    missing = [n for n in c["names"] if n not in msg]
    if missing:
        problems.append("does not name " + " / ".join(repr(m) for m in missing))
    if TEMP_NAME.search(msg):
        problems.append("message names a temporary file")
    if "filesystem error" in msg:
        problems.append("raw 'filesystem error' text")
    if len(msg) > 2000:
        problems.append(f"message of {len(msg)} characters")
    if new_paths:
        problems.append("left behind: " + ", ".join(sorted(new_paths))[:200])
    if absent_violations:
        problems.append("left behind: " + ", ".join(absent_violations))
    return ("clean" if not problems else "not-clean"), "; ".join(problems) or "refused cleanly"


def case_command(c, snapshot):
    env = " ".join(f"{k}={shlex.quote(v)}" for k, v in c.get("env", {}).items())
    if c["tool"] == "py":
        pre = f"LD_LIBRARY_PATH={snapshot}/bin PYTHONPATH={snapshot}/python HOSTILE_FIX={c['fix']} HOSTILE_SCENES={c['scenes']}"
        prelude = "import os, shadowlab as sl; FIX=os.environ['HOSTILE_FIX']; SCENE=os.environ['HOSTILE_SCENES']+'/torus-floating.json'; D=lambda o=None: sl.default_scene(o or {})\n"
        return f"cd {shlex.quote(c['dir'])} && {pre} {env} /usr/bin/python3 -c {shlex.quote(prelude + c['code'])}".replace("  ", " ")
    pre = f"LD_LIBRARY_PATH={snapshot}/bin"
    if c["tool"] == "view":
        pre += " DISPLAY=" + c["display"]
    argv = [a.decode("utf-8", "backslashreplace") if isinstance(a, bytes) else a for a in c["argv"]]
    return f"cd {shlex.quote(c['dir'])} && {pre} {env} shadowlab {' '.join(shlex.quote(a) for a in argv)}".replace("  ", " ")


def run_case(c, ctx):
    d = c["dir"]
    if os.path.lexists(d):
        subprocess.run(["chmod", "-R", "u+rwx", d], check=False)
        shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    if c.get("setup"):
        c["setup"](d)
    before = snapshot_tree(d)
    env = dict(ctx["env"])
    if c["tool"] == "view":
        env["DISPLAY"] = ctx["display"]
    env.update(c.get("env", {}))
    if c["tool"] == "py":
        argv = ["/usr/bin/python3", ctx["driver"], c["code"]]
        env["PYTHONPATH"] = os.path.join(ctx["snapshot"], "python")
    else:
        argv = [ctx["bin"]] + list(c["argv"])
    logs = os.path.join(ctx["work"], "logs")
    so, se = os.path.join(logs, c["id"] + ".out"), os.path.join(logs, c["id"] + ".err")
    rc, secs, rss, killed = run_process(argv, d, env, c["timeout"], so, se, c.get("fsize"), c.get("aslimit"))
    stdout = open(so, "rb").read().decode("utf-8", "backslashreplace")
    stderr = open(se, "rb").read().decode("utf-8", "backslashreplace")
    after = snapshot_tree(d)
    new = after - before
    temp_left = {p for p in after if TEMP_NAME.search(p)}
    for extra in c.get("watch", []):  # directories outside the case's own where output may land
        temp_left |= {os.path.join(extra, p) for p in snapshot_tree(extra) if TEMP_NAME.search(p)}
    absent_violations = [p for p in c.get("absent", []) if os.path.lexists(os.path.join(d, p))]
    if c["expect"] == "ok" or (c["expect"] == "either" and rc == 0):
        new_err = set()
    else:
        new_err = {p for p in new if not any(p == a or p.startswith(a + "/") for a in c.get("allow_new", []))}
    verdict, reason = classify(c, rc, killed, stdout, stderr, new_err, temp_left, absent_violations)
    lost = [p for p in c.get("preserve", []) if not os.path.lexists(os.path.join(d, p))]
    if lost:
        verdict, reason = "not-clean", (reason + "; " if verdict != "clean" else "") + "removed a file it did not write: " + ", ".join(lost)
    if c["tool"] == "py":
        res = None
        for line in stdout.splitlines():
            if line.startswith("@@RESULT@@ "):
                res = json.loads(line[len("@@RESULT@@ "):])
        shown = (f"{res['exc']}: {res['msg']}" if res and not res["ok"] else ("(no exception)" if res else "")) + (" | stderr: " + stderr if stderr.strip() else "")
    else:
        shown = stderr
    c["display"] = ctx["display"]
    c["driver"] = ctx["driver"]
    c["fix"], c["scenes"] = ctx["fix"], ctx["scenes"]
    return {
        "id": c["id"], "kind": c["kind"], "tool": c["tool"], "expect": c["expect"],
        "command": case_command(c, ctx["snapshot"]), "exit": rc, "seconds": round(secs, 2), "max_rss_mb": round(rss, 1),
        "stderr": shown[:300], "verdict": verdict, "reason": reason, "names": c["names"],
        "judgement": JUDGEMENT.get(c["id"], (None, None))[0], "judgement_note": JUDGEMENT.get(c["id"], (None, None))[1],
    }


DRIVER = r'''
import json, math, os, sys, pathlib
import shadowlab as sl
FIX = os.environ["HOSTILE_FIX"]
SCENES = os.environ["HOSTILE_SCENES"]
SCENE = os.path.join(SCENES, "torus-floating.json")
def D(o=None): return sl.default_scene(o or {})
try:
    exec(compile(sys.argv[1], "<case>", "exec"))
    print("@@RESULT@@ " + json.dumps({"ok": True}))
except BaseException as e:
    print("@@RESULT@@ " + json.dumps({"ok": False, "exc": type(e).__name__, "msg": str(e)}))
sys.stdout.flush()
'''


def one_line(text):
    return " | ".join(l for l in text.strip().splitlines() if l.strip()).replace("`", "'")


def write_report(results, path, args_only):
    total = len(results)
    bad = [r for r in results if r["verdict"] != "clean"]
    by_kind = {}
    for r in results:
        k = by_kind.setdefault(r["kind"], [0, 0])
        k[0] += 1
        k[1] += r["verdict"] != "clean"
    out = ["# shadowlab hostile-input battery", "",
           f"Cases: {total}; clean: {total - len(bad)}; not clean: {len(bad)}" + (f" (subset --only {args_only})" if args_only else ""), "",
           "Rerun: `/usr/bin/python3 tests/hostile/run.py` (from /work/main); one case: `--only '^ID$'`. Results: results.jsonl.", "",
           "| kind | cases | not clean |", "|---|---|---|"]
    for k, (n, b) in sorted(by_kind.items()):
        out.append(f"| {k} | {n} | {b} |")
    real = [r for r in bad if r["judgement"] == "defect"]
    exp = [r for r in bad if r["judgement"] == "expectation"]
    unj = [r for r in bad if r["judgement"] not in ("defect", "expectation")]
    out += ["", f"Judged: {len(real)} not-clean cases are real defects of shadowlab, {len(exp)} are expectation mistakes, {len(unj)} not yet judged.", ""]
    groups = {}
    for r in real:
        groups.setdefault(r["judgement_note"], []).append(r)
    if groups:
        out += ["## Real defects (grouped)", ""]
        for n, (note, rs) in enumerate(groups.items(), 1):
            out.append(f"{n}. {note}. Cases ({len(rs)}): " + ", ".join(r["id"] for r in rs) + ".")
            out.append(f"   - repro: `{rs[0]['command']}`")
            out.append(f"   - actual: exit {rs[0]['exit']}, `{one_line(rs[0]['stderr'])[:300] or '(nothing on stderr)'}`")
        out.append("")
    out += ["## Expectation mistakes found and fixed in the battery", ""]
    out += [f"- {k}: {v}" for k, v in EXPECTATION_FIXES.items()]
    out.append("")
    out += ["## Not clean, by kind", ""]
    for kind in sorted({r["kind"] for r in bad}):
        out += [f"### {kind}", ""]
        for r in [r for r in bad if r["kind"] == kind]:
            j = r["judgement"] or "unjudged"
            out.append(f"- **{r['id']}** [{j}] {r['reason']}")
            out.append(f"  - repro: `{r['command']}`")
            out.append(f"  - exit {r['exit']}" + (" (the Python driver's)" if r["tool"] == "py" else "") + f", stderr: `{one_line(r['stderr'])[:300]}`")
            if r["judgement_note"]:
                out.append(f"  - judgement: {r['judgement_note']}")
        out.append("")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--snapshot", default=os.environ.get("SHADOWLAB_SNAPSHOT"), required="SHADOWLAB_SNAPSHOT" not in os.environ)
    ap.add_argument("--only", default=None, help="regex over case ids")
    ap.add_argument("--kind", default=None, help="regex over kinds")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--results", default=None)
    ap.add_argument("--report", default=None)
    a = ap.parse_args()
    snap = os.path.abspath(a.snapshot)
    work = os.path.join(snap, "hostile-work")
    fix = os.path.join(work, "fix")
    scenes = os.path.join(snap, "scenes") if os.path.isdir(os.path.join(snap, "scenes")) else os.path.join(SOURCE, "scenes")
    ctx = {"snapshot": snap, "bin": os.path.join(snap, "bin", "shadowlab"), "work": work, "fix": fix, "scenes": scenes,
           "driver": os.path.join(work, "driver.py"), "display": None}
    from fixtures import make_fixtures
    make_fixtures(fix, scenes)
    cases = build_cases(ctx)
    ids = [c["id"] for c in cases]
    dup = {i for i in ids if ids.count(i) > 1}
    if dup:
        sys.exit(f"duplicate case ids: {sorted(dup)}")
    if a.only:
        cases = [c for c in cases if re.search(a.only, c["id"])]
    if a.kind:
        cases = [c for c in cases if re.search(a.kind, c["kind"])]
    if a.list:
        for c in cases:
            print(c["id"], c["kind"], c["expect"])
        print(len(cases), "cases")
        return
    os.makedirs(os.path.join(work, "logs"), exist_ok=True)
    os.makedirs(os.path.join(work, "cases"), exist_ok=True)
    with open(ctx["driver"], "w") as f:
        f.write(DRIVER)
    env = {k: v for k, v in os.environ.items() if not k.startswith("SHADOWLAB_")}
    env["LD_LIBRARY_PATH"] = os.path.join(snap, "bin")
    env["HOSTILE_FIX"] = fix
    env["HOSTILE_SCENES"] = scenes
    env.pop("DISPLAY", None)
    ctx["env"] = env
    for c in cases:
        c["dir"] = os.path.join(work, "cases", c["id"])
    xvfb = None
    if any(c["tool"] == "view" for c in cases):
        disp = 90 + os.getpid() % 100
        xvfb = subprocess.Popen(["Xvfb", f":{disp}", "-screen", "0", "1280x800x24", "-nolisten", "tcp"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        time.sleep(1.5)
        ctx["display"] = f":{disp}"
    t0 = time.monotonic()
    results = []
    lock = threading.Lock()
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, min(2, a.jobs))) as pool:
            futs = {pool.submit(run_case, c, ctx): c for c in cases}
            for n, fut in enumerate(concurrent.futures.as_completed(futs), 1):
                r = fut.result()
                with lock:
                    results.append(r)
                if r["verdict"] != "clean":
                    print(f"[{n}/{len(cases)}] NOT CLEAN {r['id']}: {r['reason']}", flush=True)
                elif n % 50 == 0:
                    print(f"[{n}/{len(cases)}] ...", flush=True)
    finally:
        if xvfb:
            os.killpg(xvfb.pid, signal.SIGTERM)
            xvfb.wait()
    order = {c["id"]: i for i, c in enumerate(cases)}
    results.sort(key=lambda r: order[r["id"]])
    res_path = a.results or os.path.join(snap, "results.jsonl")
    rep_path = a.report or os.path.join(snap, "report.md")
    if a.only or a.kind:  # a subset: merge into the existing results
        old = []
        if os.path.exists(res_path):
            old = [json.loads(l) for l in open(res_path) if l.strip()]
        keep = {r["id"] for r in results}
        allids = [c["id"] for c in build_cases(ctx)]
        merged = {r["id"]: r for r in old if r["id"] in allids and r["id"] not in keep}
        merged.update({r["id"]: r for r in results})
        for r in merged.values():  # judgements may have been updated since
            r["judgement"], r["judgement_note"] = JUDGEMENT.get(r["id"], (None, None))
        results = sorted(merged.values(), key=lambda r: allids.index(r["id"]))
    with open(res_path, "w") as f:
        for r in results:
            f.write(json.dumps(r) + "\n")
    write_report(results, rep_path, None)
    bad = sum(r["verdict"] != "clean" for r in results)
    print(f"{len(results)} cases, {bad} not clean, {time.monotonic() - t0:.0f} s; {res_path}, {rep_path}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
