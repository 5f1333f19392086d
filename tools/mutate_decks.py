#!/usr/bin/env python3
"""Deterministic mutation test of the bundled decks.

Derives a fixed set of broken or extreme decks from data/*.nml (same seed, same decks every
run), runs the kinetostat binary on each (table, CSV, and for a subset `-o FILE`) and checks
that the program either works or fails cleanly:

  exit-code     exit code in {0, 2, 3}: never 1 (usage) for a deck problem, never a signal, never
                over the run's limit of processor time (10 s; 60 s for the long texts and the
                heavy decks: RLIMIT_CPU, so that the machine's load cannot reach it), never
                30 times that limit of wall time (a hang that does not compute)
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

Besides the value mutations and truncations, the classes of hostile input: a deck cut just
after the '(' of an array or type name, or with such a '(' left open in mid-deck; very long
quoted texts (100 000 to 400 000 characters); comments in 8-bit encodings (CP1251 with the
byte 0xFF, Latin-1) in and before the group, and 0xFF inside a text; a --set value with a
newline or an unclosed '('; and endless input (/dev/zero, `yes | kinetostat -`), which must
stop with exit 2 within the timeout.

The classes of strings (docs/cli.md, "Strings in outputs", "Capacities of a deck"), with the
checks valid-output and expected-error:

  user_strings   (the first deck of each group; every deck with --scale 2 or more) the
                 deck under a file name with quotes, <b>, &, ]]>, a comma, newlines with
                 lines that look like DXF group codes ("  0", "EOF") and one starting INJECTED,
                 control bytes and 0xFF; its title (where it has one) and --student, --group,
                 --variant likewise: every output (table, CSV, JSON, SVG, summary, and for a
                 linkage the --at sheet, the plans, their JSON and the DXF) must pass
                 tools/output_check.py (valid-output: XML, JSON without an added key, CSV fields
                 per line, DXF group-code pairs in ASCII, no added table line, no raw 0xFF)
  set_strings    the same through --set title='...' 
  fraction       a value written "v/4": exit 2 "a fraction? write ..." (expected-error)
  after_group    an assignment after the group's closing '/': exit 2 naming it
  cp1251         the deck with a Cyrillic title and comment saved in CP1251: read (decoded),
                 never refused for its encoding; with a degree sign 0xB0 added: exit 2 naming
                 the byte
  capacity       one row of docs/cli.md's table of capacities for the deck's group, its
                 "one too many" before the '/': exit 2 "at most N ..."

--every K runs every K-th deck of the fixed set (by bundled deck, then by class), every deck
of user_strings, set_strings and the special runs, and of the other classes of strings the
first deck of each namelist group (and of each capacity row drawn) and every K-th of the others
(string_sample) (tools/test: --every 9; tools/test --long the whole set), but a heavy deck's
(HEAVY_DECKS) decoded CP1251 deck, which runs its whole analysis, with K = 1 only; with K > 1 the CSV is written with -o only (the same CSV as on
standard output, checked the same way), and a deck runs one way: the table or the CSV with -o
in turn along the fixed order (each class meets both; --modes lists them), the table only for
a class with an expected error and no outputs to check, the endless inputs at the small limit
both ways (up to the default limit with K = 1 only); with K = 1 every deck runs every way, the
CSV to standard output too. --seed N changes the random choices (tools/test --long runs the fixed set, then a
second run with a seed from the date, printed, so that a failure can be reproduced); --scale K draws K times
as many mutations per deck (--scale 14: about 12 000 decks); --budget S stops starting new
decks after S seconds (the decks not run are counted as skipped, never as failed).

Prints one line per failed (deck, check) with the mutation, the failed check and a
reproducer (the deck is written to OUT/NAME.nml: --out, by default a temporary directory made at
the first failure and printed), then per check "check NAME: ok" or
"check NAME: FAIL (n decks)", then one summary line. Exit status 0 only if nothing failed.
Standard library only.
"""

import argparse
import functools
import glob
import multiprocessing
import os
import re
import random
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import output_check  # noqa: E402  (tools/output_check.py: is an output well formed)

SEED = 20261121
#: Seconds of processor time per run of the binary (a healthy run takes milliseconds): the
#: limit is the run's own processor time (setrlimit RLIMIT_CPU: the kernel stops it with
#: SIGXCPU), not wall time, so that the machine's load cannot turn a slow run into a failure.
TIMEOUT = 10
#: Seconds of processor time per run of a deck with a text or comment of 10^5 characters or
#: more: its failing READ is repeated ~15 times by the probe that finds the line, each over
#: records as long as that line (1.2 s of processor time for 400 000 characters). Still a
#: hang detector.
LONG_TIMEOUT = 60
#: Wall time per run, as a multiple of its processor-time limit: catches a run that waits
#: without computing (a hang on a read or a lock), which RLIMIT_CPU does not; generous
#: enough that no load of the shared machine reaches it (at a load of 30 on 2 cores a run
#: gets a fifteenth of a core).
WALL_FACTOR = 30
#: Bundled decks whose every run takes over a second of processor time in the debug build (the
#: &linkage engine's steady cycles: over 361 poses 1.2 s, the engine's two turns 0.7 s, against
#: 0.05 s at most for the other decks), and the factor by which the sampled gate (--every K > 1) takes fewer of the decks of
#: their value classes: every (K * factor)-th. Their decks run with LONG_TIMEOUT (on a loaded
#: machine a run took over 10 s of wall time).
HEAVY_DECKS = {"linkage_pr3207_flywheel": 3, "linkage_engine_flywheel": 3}
#: Every how-many-th deck also gets the -o FILE run (all of them: 1).
OUTFILE_EVERY = 1
CHECKS = ["exit-code", "non-finite", "error-shape", "no-leftover", "warning-shape", "runtime-text", "valid-output",
          "expected-error"]
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


@functools.lru_cache(maxsize=None)
def masked(text):
    """The text with comments and string contents blanked (same length), for parsing (once a text:
    every value mutation of a deck parses the same text)."""
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


@functools.lru_cache(maxsize=None)
def assignments(text):
    """((name, name_start, region_end, ((el_start, el_end), ...)), ...) of a namelist deck (once a text)."""
    m = masked(text)
    hits = list(ASSIGN_RE.finditer(m))
    result = []
    for i, hit in enumerate(hits):
        end = hits[i + 1].start() if i + 1 < len(hits) else len(m)
        slash = m.find("/", hit.end(), end)
        if slash >= 0:
            end = slash
        elements = tuple((e.start() + hit.end(), e.end() + hit.end()) for e in ELEMENT_RE.finditer(m[hit.end():end]))
        if elements:
            result.append((hit.group(1), hit.start(), end, elements))
    return tuple(result)


def numeric(token):
    value = token.split("*")[-1]
    return REAL_RE.match(value) is not None


@functools.lru_cache(maxsize=None)
def value_targets(text, kind):
    """((name, index, start, end, token), ...): the elements a value kind can change (once a
    text and kind: every draw of a deck's kind chooses among the same)."""
    targets = []
    for name, _, _, els in assignments(text):
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
    return tuple(targets)


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
    targets = value_targets(text, kind)
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


#: An array or derived-type designator followed by '(' (outside comments and quotes).
PAREN_RE = re.compile(r"[A-Za-z_]\w*\(")
CP1251_COMMENT = "! \u0434\u0430\u043d\u043d\u044b\u0435 \u0434\u043b\u044f \u0440\u0430\u0441\u0447\u0451\u0442\u0430, \u044f".encode("cp1251")
LATIN1_COMMENT = "! donn\u00e9es \u00e0 v\u00e9rifier, \u00ff".encode("latin-1")


def hostile_mutations(text, raw, rng, scale):
    """[(kind, description, bytes)] of the hostile-input classes for one deck."""
    made = []
    m = masked(text)
    group = m.find("&")
    parens = [hit.end() for hit in PAREN_RE.finditer(m) if group >= 0 and hit.start() > group]
    for _ in range(2 * scale):
        if not parens:
            break
        cut = rng.choice(parens)
        made.append(("paren_cut", "cut after the '(' at byte %d" % cut, text[:cut].encode("utf-8")))
        # the same '(' left open: the rest of its line dropped, the deck goes on
        eol = text.find("\n", cut)
        eol = len(text) if eol < 0 else eol
        made.append(("paren_open", "'(' at byte %d left open, rest of its line dropped" % cut,
                     (text[:cut] + text[eol:]).encode("utf-8")))
    lines = text.split("\n")
    group_line = next((i for i, l in enumerate(lines) if l.lstrip().startswith("&")), None)
    if group_line is not None:
        for _ in range(scale):
            n = rng.choice([100000, 250000, 400000])
            title = re.search(r"title\s*=\s*'[^']*'", text)
            if title:
                new = text[:title.start()] + "title = '" + "x" * n + "'" + text[title.end():]
                made.append(("long_string", "title of %d characters" % n, new.encode("utf-8")))
            at = rng.randrange(group_line + 1, len(lines) + 1)
            new = "\n".join(lines[:at] + ["  " + rng.choice(["l", "f", "x", "phi_start"]) + " = '" + "y" * n + "'"] + lines[at:])
            made.append(("long_string", "a text of %d characters for a variable at line %d" % (n, at + 1), new.encode("utf-8")))
            at = rng.randrange(group_line + 1, len(lines) + 1)
            new = "\n".join(lines[:at] + ["  ! " + "z" * n] + lines[at:])
            made.append(("long_comment", "a comment of %d characters at line %d" % (n, at + 1), new.encode("utf-8")))
        blines = raw.split(b"\n")
        for _ in range(scale):
            comment = rng.choice([CP1251_COMMENT, LATIN1_COMMENT])
            at = rng.randrange(group_line + 1, len(blines))
            where = rng.choice(["line", "after"])
            if where == "line" or not blines[at].strip() or b"!" in blines[at] or b"'" in blines[at]:
                new = blines[:at] + [b"  " + comment] + blines[at:]
                desc = "8-bit comment line inserted at line %d" % (at + 1)
            else:
                new = blines[:at] + [blines[at] + b"  " + comment] + blines[at + 1:]
                desc = "8-bit comment after line %d" % (at + 1)
            made.append(("comment_8bit", desc, b"\n".join(new)))
        made.append(("comment_8bit", "8-bit comment before the group", CP1251_COMMENT + b"\n" + raw))
        title = re.search(rb"title\s*=\s*'", raw)
        if title:
            made.append(("ff_in_text", "byte 0xFF in the title", raw[:title.end()] + b"\xff" + raw[title.end():]))
    return made


#: Runs that are not a deck file: (name, description, how) with `how` one of these.
SPECIAL_RUNS = [
    ("endless_dev_zero", "kinetostat /dev/zero", "dev_zero"),
    ("endless_dev_zero_small", "kinetostat /dev/zero --max-deck-size 100000", "dev_zero_small"),
    ("endless_yes", "yes | kinetostat -", "yes"),
    ("endless_yes_small", "yes | kinetostat - --max-deck-size 100000", "yes_small"),
]
#: --set values that must be one-line exit 2 errors (never a crash, never two lines).
BAD_SETS = [b"title=dyad(", b"l_ab=dyad(", b"x=1\n2", b"name\nwith=1", b"dyad(1)%l2=(1", b"force(1)%value=f(",
            b"l=\xff", b"title='\xff'", b"title='a\nb'"]


#: Hostile user strings (see the docstring, user_strings).
HOSTILE_TITLE = 'x","injected":true,"y":"<b>&amp;]]>,q\x01\t%%d ^J 0 EOF \u0428\u0430\u0440\u043d\u0438\u0440 a/b ! c & d'
HOSTILE_FILE = b'x","injected":true,"<b>&]]>,\n  0\nEOF\nINJECTED\x01\xff%%d ^J.nml'
HOSTILE_FIELDS = ["--student", b'\xd0\x98\xd0\xb2"<b>&]]>,\n  0\nEOF\nINJECTED\x01\xff', "--group", b"7,\n0\nEOF",
                  "--variant", b"3\xd0"]
HOSTILE_SET = ["--set", "title='a,\"b\" <&>]]> 0 EOF \x01\t'"]
#: Outputs checked for a deck with hostile strings: (label, options, output_check format).
STRING_FORMATS = [("table", [], "table"), ("csv", ["--format", "csv"], "csv"), ("json", ["--format", "json"], "json"),
                  ("svg", ["--format", "svg"], "xml"), ("summary", ["--format", "summary"], "csv")]
AT_FORMATS = [("svg-at", ["--format", "svg", "--at", "1"], "xml"), ("plans", ["--format", "plans", "--at", "1"], "xml"),
              ("plans-json", ["--format", "json", "--at", "1", "--plans"], "json"),
              ("dxf", ["--format", "dxf", "--at", "1"], "dxf")]
LINKAGE_GROUPS = {"pr3207", "pr3050", "sixbar", "assur", "linkage"}
#: The design kinds: no sheet of forces (--format svg is a usage error).
DESIGN_GROUPS = {"gear_geometry", "planetary_synthesis", "cam_profile"}
CYRILLIC_TITLE = "\u0428\u0430\u0440\u043d\u0438\u0440\u043d\u044b\u0439 \u043c\u0435\u0445\u0430\u043d\u0438\u0437\u043c \u0401\u0451"
CYRILLIC_COMMENT = "! \u0418\u0441\u0445\u043e\u0434\u043d\u044b\u0435 \u0434\u0430\u043d\u043d\u044b\u0435, \u0432\u0430\u0440\u0438\u0430\u043d\u0442 7"
#: A row of the table of capacities in docs/cli.md: group, array, limit, what, one too many.
CAPACITY_RE = re.compile(r"^\| `&(\w+)` \| `([^`]+)`.*? \| (\d+) ([^|]+?) \| `([^`]+)` \|$")
#: Per deck name: what else its run must show (see check_deck).
SPECS = {}
#: Per deck name of a class of strings: the namelist group of the bundled deck it comes from.
GROUP_OF = {}
#: The decks of the classes of strings without outputs to check (fraction, after_group, cp1251,
#: capacity) that the sampled gate runs (string_sample); None: every one.
STRING_SAMPLE = None


def capacities(docs):
    """{group: [(limit, what, assignment)]} from the table of capacities in docs/cli.md."""
    rows = {}
    with open(docs, encoding="utf-8") as f:
        for line in f:
            m = CAPACITY_RE.match(line.strip())
            if m:
                rows.setdefault(m.group(1), []).append((m.group(3), m.group(4), m.group(5)))
    if not rows:
        raise SystemExit("mutation: no table of capacities in %s" % docs)
    return rows


def with_title(text, title):
    """The deck with its title replaced (None when it has none)."""
    m = re.search(r"title\s*=\s*'[^'\n]*'", text)
    return None if m is None else text[:m.start()] + "title = '" + title + "'" + text[m.end():]


def string_mutations(text, raw, rng, limits, every_output):
    """[(kind, description, bytes, extra arguments, spec)] of the classes of strings; the
    outputs with hostile strings (user_strings, set_strings) when `every_output`."""
    made = []
    m = masked(text)
    group = re.search(r"^\s*&(\w+)", m, re.M)
    if group is None:
        return made
    name = group.group(1).lower()
    slash = m.find("/", group.end())
    formats = [f for f in STRING_FORMATS if not (name in DESIGN_GROUPS and f[0] == "svg")]
    formats += AT_FORMATS if name in LINKAGE_GROUPS else []
    titled = with_title(text, HOSTILE_TITLE)
    data = titled.encode("utf-8") if titled else raw
    if every_output:
        made.append(("user_strings", "hostile file name, title and student fields", data, HOSTILE_FIELDS,
                     {"file": HOSTILE_FILE, "formats": formats}))
    if titled and every_output:
        made.append(("set_strings", "--set title with quotes, markup and control characters", raw, HOSTILE_SET,
                     {"formats": STRING_FORMATS}))
    targets = [(s, e) for _, _, _, els in assignments(text) for s, e in els if numeric(text[s:e])]
    if targets:
        s, e = rng.choice(targets)
        made.append(("fraction", "%s written %s/4" % (text[s:e], text[s:e]), (text[:e] + "/4" + text[e:]).encode("utf-8"),
                     [], {"expect": {"rc": 2, "stderr": r": a fraction\? "}}))
    first = assignments(text)
    if first and slash >= 0:
        n, start, end, _ = first[0]
        line = text[start:end].split("\n")[0].strip().rstrip(",")
        made.append(("after_group", "'%s' after the closing '/'" % line, (text.rstrip("\n") + "\n  " + line + "\n").encode("utf-8"),
                     [], {"expect": {"rc": 2, "stderr": r"text after the group's closing '/'"}}))
    lines = text.split("\n")
    at = next(i for i, l in enumerate(lines) if l.lstrip().startswith("&")) + 1
    ru = "\n".join(lines[:at] + ["  " + CYRILLIC_COMMENT] + lines[at:])
    ru = with_title(ru, CYRILLIC_TITLE) or ru
    try:
        made.append(("cp1251", "a Cyrillic title and comment, saved in CP1251", ru.encode("cp1251"), [],
                     {"expect": {"not_stderr": "UTF-8|CP1251"}}))
        made.append(("cp1251", "CP1251 with a degree sign (0xB0) in a comment", (ru + "\n! 30\u00b0\n").encode("cp1251"),
                     [], {"expect": {"rc": 2, "stderr": r"byte \\xB0 is neither UTF-8 nor a Cyrillic letter of CP1251"}}))
    except UnicodeEncodeError:
        pass  # a deck with a character CP1251 does not have
    if name in limits and slash >= 0:
        limit, what, assignment = rng.choice(limits[name])
        made.append(("capacity", assignment, (text[:slash] + "  " + assignment + "\n" + text[slash:]).encode("utf-8"), [],
                     {"expect": {"rc": 2, "stderr": ": at most %s %s$" % (limit, re.escape(what))}}))
    return made


def derive_decks(data_dir, seed=None, scale=1, bases=None):
    """The list of (name, description, deck bytes, extra arguments): fixed for a seed; with
    `bases` (names of bundled decks), only the decks derived from those (the same decks as in
    the whole list: each bundled deck has random choices of its own)."""
    decks = []
    seed = SEED if seed is None else seed
    limits = capacities(os.path.join(os.path.dirname(os.path.abspath(data_dir)), "docs", "cli.md"))
    groups_seen = set()
    for path in sorted(glob.glob(os.path.join(data_dir, "*.nml"))):
        base = os.path.splitext(os.path.basename(path))[0]
        with open(path, encoding="utf-8") as f:
            text = f.read()
        if bases is not None and base not in bases:
            # not derived; its group counts as seen (the first deck of each group gets the
            # outputs with hostile strings)
            group = re.search(r"^\s*&(\w+)", masked(text), re.M)
            groups_seen.add(group.group(1).lower() if group else "")
            continue
        raw = text.encode("utf-8")
        rng = random.Random("%d:%s" % (seed, base))
        made = []
        seen = {raw}
        for kind, _ in VALUE_KINDS:
            for _ in range(PICKS_PER_KIND * scale):
                for _attempt in range(5):  # a few draws for a deck not made yet
                    mut = value_mutation(text, kind, rng)
                    if mut is None or mut[1].encode("utf-8") not in seen:
                        break
                if mut is not None and mut[1].encode("utf-8") not in seen:
                    seen.add(mut[1].encode("utf-8"))
                    made.append((kind, mut[0], mut[1].encode("utf-8")))
        for _ in range(TRUNCATIONS * scale):
            cut = rng.randrange(1, len(raw))
            made.append(("truncate", "truncated at byte %d of %d" % (cut, len(raw)), raw[:cut]))
        made.append(("no_newline", "final newline removed", raw.rstrip(b"\n")))
        made.append(("bom", "UTF-8 byte order mark prepended", b"\xef\xbb\xbf" + raw))
        made.extend(hostile_mutations(text, raw, rng, scale))
        for i, (kind, desc, data) in enumerate(made):
            decks.append(("%s_%03d_%s" % (base, i + 1, kind), "%s: %s" % (base, desc), data, []))
        for j, value in enumerate(BAD_SETS):
            decks.append(("%s_set%02d_bad_set" % (base, j + 1), "%s: --set %r" % (base, value), raw,
                          ["--set", value]))
        # the outputs with hostile strings: the first deck of each group (every deck with --scale)
        group = re.search(r"^\s*&(\w+)", masked(text), re.M)
        group = group.group(1).lower() if group else ""
        every_output = scale > 1 or group not in groups_seen
        groups_seen.add(group)
        for j, (kind, desc, data, extra, spec) in enumerate(string_mutations(text, raw, rng, limits, every_output)):
            name = "%s_s%02d_%s" % (base, j + 1, kind)
            decks.append((name, "%s: %s" % (base, desc), data, extra))
            SPECS[name] = spec
            GROUP_OF[name] = group
    for name, desc, how in SPECIAL_RUNS:
        decks.append((name, desc, how, None))
    return decks


def run_limited(command, cwd, stdin, timeout):
    """subprocess.run(command, capture_output=True) with `timeout` seconds of processor time
    (RLIMIT_CPU set on the child once it runs, prlimit: a preexec function would cost a fork
    of this process per run; the kernel sends SIGXCPU beyond the limit, SIGKILL a second
    later) and WALL_FACTOR times that of wall time (subprocess.TimeoutExpired)."""
    with subprocess.Popen(command, cwd=cwd, stdin=stdin, stdout=subprocess.PIPE, stderr=subprocess.PIPE) as p:
        try:
            resource.prlimit(p.pid, resource.RLIMIT_CPU, (timeout, timeout + 1))
        except OSError:
            pass  # it has ended already
        try:
            out, err = p.communicate(timeout=timeout * WALL_FACTOR)
        except subprocess.TimeoutExpired as exc:
            p.kill()
            exc.stdout, exc.stderr = p.communicate()
            raise
        return subprocess.CompletedProcess(command, p.returncode, out, err)


def run(binary, args, cwd, endless_stdin, timeout, raw=False):
    """Runs the binary with `timeout` seconds of processor time (and WALL_FACTOR times that of
    wall time); returns (exit code, or "timeout" / "cpu-limit", stdout, stderr)."""
    try:
        if endless_stdin:
            # `yes | kinetostat -`: an endless pipe, closed when the program exits
            yes = subprocess.Popen(["yes"], stdout=subprocess.PIPE)
            try:
                p = run_limited([binary] + args, cwd, yes.stdout, timeout)
            finally:
                yes.stdout.close()
                yes.kill()
                yes.wait()
        else:
            p = run_limited([binary] + args, cwd, subprocess.DEVNULL, timeout)
        rc = p.returncode
        if rc == -signal.SIGXCPU:
            rc = "cpu-limit"
        return rc, p.stdout if raw else p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")
    except subprocess.TimeoutExpired as exc:
        return "timeout", (exc.stdout or b"").decode("utf-8", "replace"), (exc.stderr or b"").decode("utf-8", "replace")


def limit_text(rc, timeout):
    """The failure text of a run stopped by its limit (rc "cpu-limit" or "timeout")."""
    if rc == "cpu-limit":
        return "over %d s of processor time (stopped)" % timeout
    return "no end after %d s of wall time (%d s of processor time allowed)" % (timeout * WALL_FACTOR, timeout)


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


def heavy_factor(name):
    """The factor of HEAVY_DECKS of the bundled deck a derived deck comes from (1: none)."""
    return next((f for base, f in HEAVY_DECKS.items() if name.startswith(base + "_")), 1)


def one_mode_of(i, every, name, extra):
    """The one run ("table" or "-o") of the i-th derived deck in the sampled gate (every > 1):
    in turn along the sampled decks; the table (whose exit and message expected-error checks)
    for a deck of a class with an expected result and no outputs to check (fraction, group,
    capacity, cp1251); None (every run) for the full set, the decks whose outputs with hostile
    strings are checked and the special runs."""
    if every == 1 or "formats" in SPECS.get(name, {}):
        return None
    if extra is None:
        # (the endless inputs up to the default limit run with K = 1 only: sampled) the small
        # limit's runs (milliseconds) both ways
        return None
    if name in SPECS:
        return "table"
    return "table" if (i // every) % 2 == 0 else "-o"


def string_sample(decks, every):
    """The names of the decks of the classes of strings with an expected result and no outputs
    to check (fraction, after_group, cp1251, capacity) that the gate of every `every`-th deck
    runs: per class, the first deck of each namelist group (each group's reader meets every
    class), the first deck of each row of the table of capacities drawn (each row's limit and
    message), and every `every`-th of the class's other decks in the fixed order. The full set
    (every = 1) runs them all."""
    chosen, seen, count = set(), set(), {}
    for name, desc, _, extra in decks:
        spec = SPECS.get(name)
        if extra is None or spec is None or "formats" in spec:
            continue
        kind = re.match(r".*_s\d\d_(\w+)$", name).group(1)
        first = [(kind, GROUP_OF.get(name))]
        if kind == "capacity":
            first.append((kind, GROUP_OF.get(name), desc.split(": ", 1)[-1]))
        n = count.get(kind, 0)
        count[kind] = n + 1
        if every == 1 or n % every == 0 or any(key not in seen for key in first):
            chosen.add(name)
        seen.update(first)
    return chosen


def sampled(i, every, name, extra):
    """Whether the i-th derived deck runs in the gate of every `every`-th deck: every K-th of
    the value classes (of a heavy deck's, every (K * factor)-th), every deck of the classes of
    strings and every special run - but a heavy deck's deck of a class of strings that runs
    its whole analysis (the CP1251 deck read and solved: 0.75 s) only in the full set (K = 1;
    the same reader's CP1251 decks of the other decks of its group run)."""
    if every == 1:
        return True
    if extra is None:
        # the endless inputs up to the default limit (256 MiB read: 0.75 s of processor time a
        # run, 1 s with `yes`) in the full set only: both readers meet the limit, the one
        # max_deck_size of both, at 100000 bytes both ways (endless_*_small), and
        # test/cli/test_hostile_input.sh reads /dev/zero up to the default limit
        return not name.endswith(("_dev_zero", "_yes"))
    spec = SPECS.get(name)
    if spec is None:
        return i % (every * heavy_factor(name)) == 0
    if "formats" not in spec and STRING_SAMPLE is not None and name not in STRING_SAMPLE:
        return False
    return heavy_factor(name) == 1 or "formats" in spec or "rc" in spec.get("expect", {})


def list_modes(jobs):
    """Prints, per class of mutation, how many of the jobs run the table, the CSV with -o, both."""
    count = {}
    for job in jobs:
        name, one_mode = job[1], job[9]
        kind = name.rsplit("_", 1)[-1] if job[4] is not None else "special"
        count.setdefault(kind, {"table": 0, "-o": 0, "both": 0})[one_mode or "both"] += 1
    for kind in sorted(count):
        c = count[kind]
        print("%-14s table %4d  -o %4d  both %4d" % (kind, c["table"], c["-o"], c["both"]))
    return 0


def set_cpu_limit(seconds):
    """Sets TIMEOUT (and LONG_TIMEOUT, six times it) in this process (a worker's initializer)."""
    global TIMEOUT, LONG_TIMEOUT
    TIMEOUT, LONG_TIMEOUT = seconds, 6 * seconds


def timeout_of(name):
    """Wall-time limit of one run of a derived deck, s."""
    return LONG_TIMEOUT if "_long_" in name or heavy_factor(name) > 1 else TIMEOUT


def check_deck(job):
    """Runs one deck; returns (name, description, [(check, mode, detail)], selfcheck_warning)."""
    binary, name, desc, data, extra, with_file, deadline, spec, stdout_csv, one_mode = job
    failures = []
    selfcheck = False
    table_run = None
    if deadline is not None and time.time() > deadline:
        return name, desc, None, False, None
    work = tempfile.mkdtemp(prefix="ks_mut_")
    try:
        stdin_endless = False
        if extra is None:
            # a special run: endless input
            source = {"dev_zero": "/dev/zero", "dev_zero_small": "/dev/zero"}.get(data, "-")
            limit = ["--max-deck-size", "100000"] if data.endswith("_small") else []
            stdin_endless = data.startswith("yes")
            modes = [("table", [source] + limit)]
            if with_file:
                modes.append(("-o", [source, "--format", "csv", "-o", "out.csv"] + limit))
            if one_mode:
                modes = [m for m in modes if m[0] == one_mode]
        else:
            file_name = (spec or {}).get("file", b"deck.nml")
            with open(os.path.join(os.fsencode(work), file_name), "wb") as f:
                f.write(data)
            modes = [("table", [file_name] + extra)]
            if stdout_csv or not with_file:
                modes.append(("csv", [file_name, "--format", "csv"] + extra))
            if with_file:
                modes.append(("-o", [file_name, "--format", "csv", "-o", "out.csv"] + extra))
            if one_mode:
                modes = [m for m in modes if m[0] == one_mode]
        for mode, args in modes:
            rc, out, err = run(binary, args, work, stdin_endless, timeout_of(name))
            if extra is None and rc != 2:
                failures.append(("exit-code", mode, "endless input: exit %s, expected 2 (the deck limit)" % rc))
            if mode in ("table", one_mode):
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
            if not isinstance(rc, int) or rc not in (0, 2, 3):
                what = limit_text(rc, timeout_of(name)) if rc in ("timeout", "cpu-limit") else (
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
        if spec:
            failures += string_checks(binary, spec, file_name, extra, work, table_run, timeout_of(name))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return name, desc, failures, selfcheck, table_run


def string_checks(binary, spec, file_name, extra, work, table_run, timeout):
    """The failures of valid-output (every format of spec["formats"] well formed, no raw 0xFF,
    no raw <b> in XML) and expected-error (the table run's exit code and message)."""
    failures = []
    for _, options, form in spec.get("formats", []):
        label = " ".join(options) or "table"
        rc, out, err = run(binary, [file_name] + options + extra, work, False, timeout, raw=True)
        if rc in ("timeout", "cpu-limit") or rc not in (0, 2, 3):
            what = limit_text(rc, timeout) if rc in ("timeout", "cpu-limit") else "exit %s" % rc
            failures.append(("exit-code", label, "%s; stderr: %s" % (what, err.strip()[:200])))
        if rc != 0:
            continue
        bad = []
        output_check.CHECKS[form](out, bad)
        for raw_text in [b"\xff"] + ([b"<b>"] if form == "xml" else []):
            if raw_text in out:
                bad.append("the raw bytes %r" % raw_text)
        if bad:
            failures.append(("valid-output", label, "; ".join(bad[:3])))
    expect = spec.get("expect")
    if expect and table_run:
        rc, err = table_run
        if "rc" in expect and rc != expect["rc"]:
            failures.append(("expected-error", "table", "exit %s, expected %s: %s" % (rc, expect["rc"], err.strip()[:200])))
        elif "stderr" in expect and not re.search(expect["stderr"], err):
            failures.append(("expected-error", "table", "stderr does not match /%s/: %s" % (expect["stderr"], err.strip()[:200])))
        elif "not_stderr" in expect and re.search(expect["not_stderr"], err):
            failures.append(("expected-error", "table", "stderr matches /%s/: %s" % (expect["not_stderr"], err.strip()[:200])))
    return failures


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
    ap.add_argument("--out", default=None,
                    help="where failing decks are written (reproducers; default: a new temporary "
                         "directory, made when a deck fails and printed)")
    ap.add_argument("--list", action="store_true", help="list the decks and their mutations, run nothing")
    ap.add_argument("--only", default="", help="run only decks whose name contains this text")
    ap.add_argument("--deck", action="append", default=None,
                    help="derive only from this bundled deck (data/DECK.nml; repeatable): the same decks as "
                         "in the whole set, made faster (with --only)")
    ap.add_argument("--selfcheck", action="store_true", help="also list decks that gave a self-check warning")
    ap.add_argument("--jobs", type=int, default=2, help="worker processes (2)")
    ap.add_argument("--unnamed", action="store_true",
                    help="list the input errors of single-variable mutations that do not name the variable")
    ap.add_argument("--seed", type=int, default=None, help="seed of the random choices (default: the fixed %d)" % SEED)
    ap.add_argument("--scale", type=int, default=1, help="draw K times as many mutations per deck (1)")
    ap.add_argument("--every", type=int, default=1,
                    help="run every K-th derived deck (in the fixed order: by bundled deck, then by class), "
                         "every deck with hostile strings in its outputs and every special run, and of the "
                         "other classes of strings the first of each group and every K-th (1: all)")
    ap.add_argument("--modes", action="store_true",
                    help="list, per class of mutation, the decks run as a table, as CSV with -o, and both; run nothing")
    ap.add_argument("--budget", type=float, default=0.0,
                    help="seconds after which no new deck is started (0: no limit); decks not run are skipped")
    ap.add_argument("--cpu-limit", type=int, default=TIMEOUT,
                    help="seconds of processor time per run (%d; six times it for the long texts and the "
                         "heavy decks)" % TIMEOUT)
    args = ap.parse_args()
    set_cpu_limit(max(1, args.cpu_limit))

    if args.seed is not None:
        print("mutation: seed %d (reproduce: python3 tools/mutate_decks.py --seed %d%s)" % (
            args.seed, args.seed, " --scale %d" % args.scale if args.scale != 1 else ""))
    decks = derive_decks(args.data, args.seed, max(1, args.scale), args.deck)
    if args.deck is None and len(decks) < 500:
        print("mutation: only %d decks derived (at least 500 expected)" % len(decks))
        return 1
    if args.list:
        for name, desc, _, _ in decks:
            print("%s  %s" % (name, desc))
        print("%d decks" % len(decks))
        return 0
    if not args.bin or not os.access(args.bin, os.X_OK):
        print("mutation: no kinetostat binary (use --bin or $KINETOSTAT)")
        return 1
    binary = os.path.abspath(args.bin)
    deadline = time.time() + args.budget if args.budget > 0 else None
    every = max(1, args.every)
    global STRING_SAMPLE
    STRING_SAMPLE = string_sample(decks, every)
    # the sampled gate (--every K > 1) writes the CSV with -o only: the same CSV as on
    # standard output, checked the same way (non-finite, error shape, runtime text) and for
    # leftovers; --every 1 runs both
    # ... and runs an ordinary derived deck one way, the table or the CSV with -o, in turn
    # along the fixed order (every class meets both), a deck of a class with an expected error
    # the table only (one_mode_of; tools/mutate_decks.py --every 9 --modes lists them)
    jobs = [(binary, name, desc, data, extra, i % OUTFILE_EVERY == 0, deadline, SPECS.get(name), every == 1,
             one_mode_of(i, every, name, extra))
            for i, (name, desc, data, extra) in enumerate(decks) if args.only in name and sampled(i, every, name, extra)]
    if args.modes:
        return list_modes(jobs)
    if args.seed is not None:
        # a randomized run under a time budget runs the decks in a random order, so that
        # every class has its chance before the budget ends
        random.Random(args.seed).shuffle(jobs)
    data_of = {name: (data if extra is not None else b"") for name, _, data, extra in decks}
    extra_of = {name: extra for name, _, _, extra in decks}
    with multiprocessing.Pool(args.jobs, initializer=set_cpu_limit, initargs=(TIMEOUT,)) as pool:
        results = pool.map(check_deck, jobs, chunksize=8)
    skipped = sum(1 for r in results if r[2] is None)
    results = [r for r in results if r[2] is not None]

    failed_by_check = {c: 0 for c in CHECKS}
    failed_decks = 0
    selfcheck_decks = []
    if args.out and os.path.isdir(args.out):
        for old in glob.glob(os.path.join(args.out, "*.nml")):
            os.remove(old)
    named = unnamed = 0
    for name, desc, failures, selfcheck, table_run in results:
        kind = next((k for k in SINGLE_VARIABLE_KINDS if name.endswith("_" + k)), None)
        if extra_of[name] != []:
            kind = None  # a special run or a --set: not a deck's single-variable mutation
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
        if args.out is None:
            args.out = tempfile.mkdtemp(prefix="kinetostat_mutation_")
            print("mutation: the failing decks are written to %s" % args.out)
        os.makedirs(args.out, exist_ok=True)
        repro = os.path.join(args.out, name + ".nml")
        with open(repro, "wb") as f:
            f.write(data_of[name])
        rel = os.path.relpath(repro, os.getcwd())
        if rel.startswith(".."):
            rel = repro
        seen = set()
        for check, mode, detail in failures:
            if check not in seen:
                failed_by_check[check] += 1
                seen.add(check)
            opts = {"table": "", "csv": " --format csv", "-o": " --format csv -o /tmp/ks_mut.csv"}.get(mode, " " + mode)
            if extra_of[name]:
                opts += " " + " ".join(repr(a) for a in extra_of[name])
            if extra_of[name] is None:
                rel = desc
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
    runs = sum(1 if j[9] else (1 if j[4] is None else 1 + (j[8] or not j[5])) + j[5] for j in jobs) - 3 * skipped
    print("mutation: %d decks, %d runs, %d decks failed (%s); %d self-check warnings (not counted)%s" % (
        len(jobs) - skipped, runs, failed_decks,
        ", ".join("%s %d" % (c, failed_by_check[c]) for c in CHECKS), len(selfcheck_decks),
        "; %d decks skipped (time budget)" % skipped if skipped else ""))
    return 0 if failed_decks == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
