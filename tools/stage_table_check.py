#!/usr/bin/env python3
"""Check the table of stages and deck kinds of docs/linkage.md ("Stages and deck kinds") against
the program (standard library only).

usage: tools/stage_table_check.py KINETOSTAT docs/linkage.md

Every cell of the table is "yes" (or "yes (its translation)": the stage runs on the deck's
`&linkage` translation) or a refusal quoting (in backticks) a part of the program's
one-line error. For every cell the command below is run on the kind's deck: a "yes" must exit 0
(warnings silenced by --quiet), a refusal must exit 2 with exactly one stderr line
"kinetostat: error: ..." that contains the quoted text, and nothing on stdout; the namelist's
bare "unknown variable" is no refusal (a stage a kind lacks names the reason and the way out). Prints one line
per failing cell and exits 1 when any fails; a row or a kind of the table that the checker
does not know, or one it knows that the table lacks, fails too.
"""
import re
import subprocess
import sys

KINDS = ["&pr3207", "&pr3050", "&sixbar", "&assur", "&linkage"]
DECK = {"&pr3207": "data/pr3207.nml", "&pr3050": "data/pr3050.nml", "&sixbar": "data/sixbar.nml",
        "&assur": "data/assur_fourbar.nml", "&linkage": "data/linkage_fourbar.nml"}
GIVEN = ["--set", "dynamics='given'", "--set", "j_flywheel=1000"]
FRICTION = {"&pr3207": ["--set", "crank_f=0.1"], "&pr3050": ["--set", "crank_f=0.1"],
            "&sixbar": ["--set", "crank_f=0.1"], "&assur": ["--set", "crank_f=0.1", "--set", "crank_r=0.01"],
            "&linkage": ["--set", "pair(1)%f=0.1", "--set", "pair(1)%r=0.01"]}
TABLE = {"&pr3207": ["--set", "force(1)%table=0,1,360,1"], "&pr3050": ["--set", "force(1)%table=0,1,360,1"],
         "&sixbar": ["--set", "force(1)%table=0,1,360,1"]}


def command(row, kind):
    """The arguments that exercise stage `row` on deck kind `kind` (after the binary)."""
    deck = DECK[kind]
    if row == "force analysis: table, CSV, JSON, npy, summary, sweep, diff":
        return [deck]
    if row == "SVG sheet of the run (`--format svg`)":
        return [deck, "--format", "svg"]
    if row == "the mechanism at a step (`--format svg --at K`)":
        return [deck, "--format", "svg", "--at", "2"]
    if row == "plans of the graphical method (`--plans`, `--format plans`)":
        return [deck, "--format", "json", "--at", "2", "--plans"]
    if row == "structural analysis (`kinetostat structure`)":
        return ["structure", deck]
    if row == "shaking force and moment (`--shaking`)":
        return [deck, "--shaking"]
    if row == "counterweight balancing (`kinetostat balance`)":
        # a shaper's and the six-bar's slider leave the total centre of mass moving: full balance
        # is refused (exit 3, as &assur's twin); the crank alone balances
        return ["balance", deck] + (["--method", "crank"] if kind in ("&pr3207", "&sixbar") else [])
    if row == "friction in the pairs, efficiency":
        return [deck] + FRICTION[kind]
    if row == "reduced quantities (`dynamics = 'reduced'`)":
        return [deck, "--set", "dynamics='reduced'"]
    # PR 3050 has no j_flywheel: 'steady' alone meets its refusal
    given = ["--set", "dynamics='steady'"] if kind == "&pr3050" else GIVEN
    if row == "steady cycle, flywheel, true motion (`'steady'`, `'given'`)":
        return [deck] + given
    if row == "driving-moment table (`md_table`)":
        return [deck] + given[:2] + ["--set", "md_table=0,1,180,2"] + given[2:]
    if row == "a cycle of two turns (`cycle = 720`)":
        if kind == "&assur":
            return ["data/assur_engine_flywheel.nml"]
        if kind == "&linkage":
            return [deck] + GIVEN + ["--set", "cycle=720", "--set", "n=49"]
        return [deck] + given[:2] + ["--set", "cycle=720"] + given[2:]
    if row == "load tables over a link's position (`force(i)%table`)":
        if kind == "&assur":
            return ["data/assur_engine_flywheel.nml"]
        if kind == "&linkage":
            return ["data/linkage_engine_flywheel.nml"]
        return [deck] + TABLE[kind]
    return None


def main():
    binary, page = sys.argv[1], sys.argv[2]
    lines = open(page, encoding="utf-8").read().splitlines()
    start = next((i for i, l in enumerate(lines) if l.startswith("| stage |")), None)
    if start is None:
        print("stage_table_check: no table starting '| stage |' in " + page)
        return 1
    head = [c.strip() for c in lines[start].strip("|").split("|")]
    bad = []
    if head[1:] != KINDS:
        bad.append(f"the table's kinds {head[1:]} are not {KINDS}")
    seen = set()
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]]
        row = cells[0]
        seen.add(row)
        for kind, cell in zip(KINDS, cells[1:]):
            args = command(row, kind)
            if args is None:
                bad.append(f"row {row!r}: unknown to the checker")
                break
            p = subprocess.run([binary] + args + ["--quiet"] * (args[0] not in ("structure", "balance")),
                               capture_output=True, text=True)
            err = p.stderr.strip().splitlines()
            if cell in ("yes", "yes (its translation)"):
                if p.returncode != 0:
                    bad.append(f"{row} / {kind}: 'yes' but exit {p.returncode}: {p.stderr.strip()[:300]}")
                continue
            quoted = re.findall(r"`([^`]+)`", cell)
            if not quoted:
                bad.append(f"{row} / {kind}: cell {cell!r} is neither 'yes' nor a refusal quoting its message")
                continue
            if p.returncode != 2 or len(err) != 1 or not err[0].startswith("kinetostat: error: ") or p.stdout:
                bad.append(f"{row} / {kind}: refusal expected (exit 2, one line), got exit {p.returncode}: "
                           f"{p.stderr.strip()[:300]}")
                continue
            if "unknown variable" in err[0]:
                bad.append(f"{row} / {kind}: refused with the namelist's bare {err[0]!r}: a stage a kind lacks is "
                           "refused naming the reason and the way out")
                continue
            if quoted[-1] not in err[0]:
                bad.append(f"{row} / {kind}: message {err[0]!r} does not contain {quoted[-1]!r}")
    for row in ("structural analysis (`kinetostat structure`)", "friction in the pairs, efficiency",
                "steady cycle, flywheel, true motion (`'steady'`, `'given'`)", "a cycle of two turns (`cycle = 720`)"):
        if row not in seen:
            bad.append(f"row {row!r} missing from the table")
    print("\n".join(bad) or f"stage table: {len(seen)} stages x {len(KINDS)} kinds ok")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
