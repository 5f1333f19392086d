#!/usr/bin/env python3
"""Deterministic mutation test of the bundled decks.

Derives a fixed set of broken or extreme decks from data/*.nml (same seed, same decks every
run), runs the kinetostat binary on each (table, CSV, and for a subset `-o FILE`) and checks
that the program either works or fails cleanly:

  exit-code     exit code in {0, 2, 3}: never 1 (usage) for a deck problem, never a signal or
                a timeout
  non-finite    no NaN / Inf / Infinity and no overflow stars in stdout or the -o file
                (a '*' is legitimate only inside a unit name between letters/digits, as in
                "N*m", "kg*m^2", "(M1*u_1H)" of the goldens; every other '*' is flagged)
  error-shape   on a non-zero exit: stderr is exactly one line "kinetostat: error: ...",
                stdout is empty
  no-leftover   with -o: on a non-zero exit neither FILE nor FILE.tmp.* is left; on exit 0
                no FILE.tmp.* is left and FILE exists
  warning-shape on exit 0: every stderr line starts with "kinetostat: warning: "
  runtime-text  no Fortran runtime text ("Fortran runtime error", "Error termination",
                "Backtrace", "Program received signal") in stdout, stderr or the file

Prints one line per failed (deck, check) with the mutation, the failed check and a
reproducer (the deck is written to OUT/NAME.nml), then per check "check NAME: ok" or
"check NAME: FAIL (n decks)", then one summary line. Exit status 0 only if nothing failed.
Standard library only.
"""

import argparse
import glob
import multiprocessing
import os
import re
import random
import shutil
import subprocess
import sys
import tempfile

SEED = 20261121
#: Seconds per run of the binary (a healthy run takes milliseconds).
TIMEOUT = 10
#: Every how-many-th deck also gets the -o FILE run (all of them: 1).
OUTFILE_EVERY = 1
CHECKS = ["exit-code", "non-finite", "error-shape", "no-leftover", "warning-shape", "runtime-text"]
RUNTIME_TEXT = ["Fortran runtime error", "Error termination", "Backtrace", "Program received signal"]
NONFINITE_RE = re.compile(r"(?<![A-Za-z])(nan|inf|infinity)(?![A-Za-z])", re.IGNORECASE)
UNIT_STAR_RE = re.compile(r"(?<=[A-Za-z0-9)])\*(?=[A-Za-z(])")

ASSIGN_RE = re.compile(r"(?<![\w%)])([A-Za-z_]\w*(?:\(\s*\d+\s*\))?(?:%[A-Za-z_]\w*)?)\s*=")
ELEMENT_RE = re.compile(r"[^\s,]+")
INT_RE = re.compile(r"^[+-]?\d+$")
REAL_RE = re.compile(r"^[+-]?(\d+\.\d*|\.\d+|\d+)([eEdD][+-]?\d+)?$")

VALUE_KINDS = [
    ("delete", "delete the assignment"),
    ("string", "value -> 'abc'"),
    ("logical", "value -> .true."),
    ("int_for_real", "real value -> integer"),
    ("real_for_int", "integer value -> real x.5"),
    ("decimal_comma", "value -> 0,11 (decimal comma)"),
    ("big", "value -> 1e300"),
    ("neg_big", "value -> -1e300"),
    ("tiny", "value -> 1e-300"),
    ("e20", "value -> 1e20"),
    ("em20", "value -> 1e-20"),
    ("e15", "value -> 1e15"),
    ("zero", "value -> 0"),
    ("negative", "value -> its negative"),
    ("nan", "value -> NaN"),
    ("inf", "value -> Inf"),
    ("neg_inf", "value -> -Inf"),
    ("lengthen", "array one element longer"),
    ("shorten", "array one element shorter"),
]
REPLACEMENT = {"string": "'abc'", "logical": ".true.", "decimal_comma": "0,11", "big": "1e300",
               "neg_big": "-1e300", "tiny": "1e-300", "e20": "1e20", "em20": "1e-20",
               "e15": "1e15", "zero": "0", "nan": "NaN", "inf": "Inf", "neg_inf": "-Inf"}
#: Random choices (assignment, element) per value kind and deck; truncations per deck.
PICKS_PER_KIND = 2
TRUNCATIONS = 3


def masked(text):
    """The text with comments and string contents blanked (same length), for parsing."""
    out = []
    quote = None
    comment = False
    for ch in text:
        if comment:
            out.append("\n" if ch == "\n" else " ")
            if ch == "\n":
                comment = False
        elif quote:
            if ch == quote:
                quote = None
                out.append(ch)
            else:
                out.append("\n" if ch == "\n" else "x")
        elif ch in "'\"":
            quote = ch
            out.append(ch)
        elif ch == "!":
            comment = True
            out.append(" ")
        else:
            out.append(ch)
    return "".join(out)


def assignments(text):
    """[(name, name_start, region_end, [(el_start, el_end), ...])] of a namelist deck."""
    m = masked(text)
    hits = list(ASSIGN_RE.finditer(m))
    result = []
    for i, hit in enumerate(hits):
        end = hits[i + 1].start() if i + 1 < len(hits) else len(m)
        slash = m.find("/", hit.end(), end)
        if slash >= 0:
            end = slash
        elements = [(e.start() + hit.end(), e.end() + hit.end()) for e in ELEMENT_RE.finditer(m[hit.end():end])]
        if elements:
            result.append((hit.group(1), hit.start(), end, elements))
    return result


def numeric(token):
    value = token.split("*")[-1]
    return REAL_RE.match(value) is not None


def value_mutation(text, kind, rng):
    """(description, new_text) for a value kind, or None when the deck offers no target."""
    assigns = assignments(text)
    if kind == "delete":
        name, start, end, _ = rng.choice(assigns)
        return "delete %s" % name, text[:start] + text[end:]
    if kind in ("lengthen", "shorten"):
        pool = assigns if kind == "lengthen" else [a for a in assigns if len(a[3]) >= 2]
        if not pool:
            return None
        name, _, _, els = rng.choice(pool)
        if kind == "lengthen":
            s, e = els[-1]
            return "%s: one element more" % name, text[:e] + ", " + text[s:e] + text[e:]
        prev_end, (s, e) = els[-2][1], els[-1]
        return "%s: last element dropped" % name, text[:prev_end] + text[e:]
    targets = []
    for name, _, _, els in assigns:
        for idx, (s, e) in enumerate(els):
            tok = text[s:e]
            if kind == "int_for_real" and not (numeric(tok) and not INT_RE.match(tok.split("*")[-1])):
                continue
            if kind == "real_for_int" and not INT_RE.match(tok.split("*")[-1]):
                continue
            if kind in ("zero", "negative", "big", "neg_big", "tiny", "e20", "em20", "e15") and not numeric(tok):
                continue
            if kind in ("zero", "negative") and float(tok.split("*")[-1].replace("d", "e").replace("D", "e")) == 0.0:
                continue
            targets.append((name, idx, s, e, tok))
    if not targets:
        return None
    name, idx, s, e, tok = rng.choice(targets)
    prefix = tok[:tok.index("*") + 1] if "*" in tok else ""
    value = tok[len(prefix):]
    if kind == "int_for_real":
        new = prefix + str(int(round(float(value.replace("d", "e").replace("D", "e")))))
    elif kind == "real_for_int":
        new = prefix + value + ".5"
    elif kind == "negative":
        new = prefix + (value[1:] if value.startswith("-") else "-" + value.lstrip("+"))
    elif kind in ("string", "logical", "decimal_comma"):
        new = REPLACEMENT[kind]
    else:
        new = prefix + REPLACEMENT[kind]
    return "%s[%d]: %s -> %s" % (name, idx + 1, tok, new), text[:s] + new + text[e:]


def derive_decks(data_dir):
    """The fixed list of (name, description, deck bytes)."""
    decks = []
    for path in sorted(glob.glob(os.path.join(data_dir, "*.nml"))):
        base = os.path.splitext(os.path.basename(path))[0]
        with open(path, encoding="utf-8") as f:
            text = f.read()
        raw = text.encode("utf-8")
        rng = random.Random("%d:%s" % (SEED, base))
        made = []
        seen = {raw}
        for kind, _ in VALUE_KINDS:
            for _ in range(PICKS_PER_KIND):
                for _attempt in range(5):  # a few draws for a deck not made yet
                    mut = value_mutation(text, kind, rng)
                    if mut is None or mut[1].encode("utf-8") not in seen:
                        break
                if mut is not None and mut[1].encode("utf-8") not in seen:
                    seen.add(mut[1].encode("utf-8"))
                    made.append((kind, mut[0], mut[1].encode("utf-8")))
        for _ in range(TRUNCATIONS):
            cut = rng.randrange(1, len(raw))
            made.append(("truncate", "truncated at byte %d of %d" % (cut, len(raw)), raw[:cut]))
        made.append(("no_newline", "final newline removed", raw.rstrip(b"\n")))
        made.append(("bom", "UTF-8 byte order mark prepended", b"\xef\xbb\xbf" + raw))
        for i, (kind, desc, data) in enumerate(made):
            decks.append(("%s_%03d_%s" % (base, i + 1, kind), "%s: %s" % (base, desc), data))
    return decks


def run(binary, args, cwd):
    try:
        p = subprocess.run([binary] + args, cwd=cwd, capture_output=True, timeout=TIMEOUT)
        return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")
    except subprocess.TimeoutExpired as exc:
        return "timeout", (exc.stdout or b"").decode("utf-8", "replace"), (exc.stderr or b"").decode("utf-8", "replace")


def bad_text(text):
    """A short reason when text holds non-finite numbers or overflow stars, else None."""
    m = NONFINITE_RE.search(text)
    if m:
        line = text[:m.start()].count("\n") + 1
        return "%r on line %d" % (m.group(0), line)
    stripped = UNIT_STAR_RE.sub("", text)
    if "*" in stripped:
        pos = stripped.index("*")
        line = stripped[:pos].count("\n") + 1
        return "'*' on line %d: %s" % (line, stripped.splitlines()[line - 1].strip()[:80])
    return None


def check_deck(job):
    """Runs one deck; returns (name, description, [(check, mode, detail)], selfcheck_warning)."""
    binary, name, desc, data, with_file = job
    failures = []
    selfcheck = False
    table_run = None
    work = tempfile.mkdtemp(prefix="ks_mut_")
    try:
        deck = os.path.join(work, "deck.nml")
        with open(deck, "wb") as f:
            f.write(data)
        modes = [("table", ["deck.nml"]), ("csv", ["deck.nml", "--format", "csv"])]
        if with_file:
            modes.append(("-o", ["deck.nml", "--format", "csv", "-o", "out.csv"]))
        for mode, args in modes:
            rc, out, err = run(binary, args, work)
            if mode == "table":
                table_run = (rc, err)
            file_text = ""
            if mode == "-o":
                target = os.path.join(work, "out.csv")
                leftovers = glob.glob(target + ".tmp.*")
                if os.path.exists(target):
                    with open(target, encoding="utf-8", errors="replace") as f:
                        file_text = f.read()
                if rc != 0 and (os.path.exists(target) or leftovers):
                    failures.append(("no-leftover", mode, "exit %s left %s" % (rc, "FILE" if os.path.exists(target) else "FILE.tmp.*")))
                elif rc == 0 and (leftovers or not os.path.exists(target)):
                    failures.append(("no-leftover", mode, "exit 0 but " + ("FILE.tmp.* left" if leftovers else "no FILE")))
                for p in [target] + leftovers:
                    if os.path.exists(p):
                        os.remove(p)
            if rc == "timeout" or not isinstance(rc, int) or rc not in (0, 2, 3):
                what = "timeout after %d s" % TIMEOUT if rc == "timeout" else (
                    "killed by signal %d" % -rc if rc < 0 else "exit %d" % rc)
                failures.append(("exit-code", mode, "%s; stderr: %s" % (what, err.strip()[:200])))
            for label, text in (("stdout", out), ("file", file_text)):
                reason = bad_text(text)
                if reason:
                    failures.append(("non-finite", mode, "%s: %s" % (label, reason)))
            lines = err.splitlines()
            if rc != 0:
                if len(lines) != 1 or not lines[0].startswith("kinetostat: error: "):
                    failures.append(("error-shape", mode, "exit %s, stderr has %d lines: %s" % (rc, len(lines), err.strip()[:200])))
                elif out:
                    failures.append(("error-shape", mode, "exit %s with %d bytes on stdout" % (rc, len(out))))
            else:
                bad = [l for l in lines if not l.startswith("kinetostat: warning: ")]
                if bad:
                    failures.append(("warning-shape", mode, "stderr line: %s" % bad[0][:200]))
                if any("self-check failed" in l for l in lines):
                    selfcheck = True
            for label, text in (("stdout", out), ("stderr", err), ("file", file_text)):
                hit = [t for t in RUNTIME_TEXT if t in text]
                if hit:
                    failures.append(("runtime-text", mode, "%s contains %r" % (label, hit[0])))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return name, desc, failures, selfcheck, table_run


#: Mutations of one variable's value (the variable is the first word of the description).
SINGLE_VARIABLE_KINDS = {kind for kind, _ in VALUE_KINDS}
MUTATED_RE = re.compile(r"^(?:delete )?([A-Za-z_]\w*)(?:\(\s*\d+\s*\))?(?:%([A-Za-z_]\w*))?")


def names_variable(desc, message):
    """Whether an error message names the variable a single-variable mutation changed (its
    name, and for a derived-type member the member too, as words, in any case)."""
    m = MUTATED_RE.match(desc.split(": ", 1)[1])
    if not m:
        return False
    words = set(re.findall(r"[a-z_][a-z0-9_]*", message.lower()))
    return all(part.lower() in words for part in m.groups() if part)


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=os.environ.get("KINETOSTAT"), help="the kinetostat binary ($KINETOSTAT)")
    ap.add_argument("--data", default=os.path.join(root, "data"), help="directory of the bundled decks")
    ap.add_argument("--out", default=os.path.join(root, "test", "out", "mutation"),
                    help="where failing decks are written (reproducers)")
    ap.add_argument("--list", action="store_true", help="list the decks and their mutations, run nothing")
    ap.add_argument("--only", default="", help="run only decks whose name contains this text")
    ap.add_argument("--selfcheck", action="store_true", help="also list decks that gave a self-check warning")
    ap.add_argument("--jobs", type=int, default=2, help="worker processes (2)")
    ap.add_argument("--unnamed", action="store_true",
                    help="list the input errors of single-variable mutations that do not name the variable")
    args = ap.parse_args()

    decks = derive_decks(args.data)
    if len(decks) < 500:
        print("mutation: only %d decks derived (at least 500 expected)" % len(decks))
        return 1
    if args.list:
        for name, desc, _ in decks:
            print("%s  %s" % (name, desc))
        print("%d decks" % len(decks))
        return 0
    if not args.bin or not os.access(args.bin, os.X_OK):
        print("mutation: no kinetostat binary (use --bin or $KINETOSTAT)")
        return 1
    binary = os.path.abspath(args.bin)
    jobs = [(binary, name, desc, data, i % OUTFILE_EVERY == 0)
            for i, (name, desc, data) in enumerate(decks) if args.only in name]
    data_of = {name: data for name, _, data in decks}
    with multiprocessing.Pool(args.jobs) as pool:
        results = pool.map(check_deck, jobs, chunksize=8)

    failed_by_check = {c: 0 for c in CHECKS}
    failed_decks = 0
    selfcheck_decks = []
    if os.path.isdir(args.out):
        for old in glob.glob(os.path.join(args.out, "*.nml")):
            os.remove(old)
    named = unnamed = 0
    for name, desc, failures, selfcheck, table_run in results:
        kind = next((k for k in SINGLE_VARIABLE_KINDS if name.endswith("_" + k)), None)
        if kind and table_run and table_run[0] == 2:
            if names_variable(desc, table_run[1]):
                named += 1
            else:
                unnamed += 1
                if args.unnamed:
                    print("UNNAMED %s [%s]: %s" % (name, desc, table_run[1].strip()[:300]))
        if selfcheck:
            selfcheck_decks.append((name, desc))
        if not failures:
            continue
        failed_decks += 1
        os.makedirs(args.out, exist_ok=True)
        repro = os.path.join(args.out, name + ".nml")
        with open(repro, "wb") as f:
            f.write(data_of[name])
        rel = os.path.relpath(repro, os.getcwd())
        seen = set()
        for check, mode, detail in failures:
            if check not in seen:
                failed_by_check[check] += 1
                seen.add(check)
            opts = {"table": "", "csv": " --format csv", "-o": " --format csv -o /tmp/ks_mut.csv"}[mode]
            print("FAIL %s [%s] %s (%s): %s; reproduce: %s %s%s" % (name, desc, check, mode, detail, "$KINETOSTAT", rel, opts))
    if args.selfcheck:
        for name, desc in selfcheck_decks:
            print("SELF-CHECK WARNING %s [%s]" % (name, desc))
    for check in CHECKS:
        n = failed_by_check[check]
        print("check %s: %s" % (check, "ok" if n == 0 else "FAIL (%d decks)" % n))
    if named + unnamed:
        print("named: %d of %d input errors (exit 2) of single-variable mutations name the variable (%.0f %%)" % (
            named, named + unnamed, 100.0 * named / (named + unnamed)))
    runs = sum(3 if j[4] else 2 for j in jobs)
    print("mutation: %d decks, %d runs, %d decks failed (%s); %d self-check warnings (not counted)" % (
        len(jobs), runs, failed_decks,
        ", ".join("%s %d" % (c, failed_by_check[c]) for c in CHECKS), len(selfcheck_decks)))
    return 0 if failed_decks == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
