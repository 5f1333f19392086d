#!/usr/bin/env python3
"""The man page and the bash completion against the program's option table.

usage: tools/check_options.py KINETOSTAT [--completion FILE] [--man FILE] [--docs FILE]

The option table (src/cli/kinetostat_cli_options.f90) writes --help's synopsis and the
usage line; this reads them back from the binary and checks, for every subcommand:
- the usage line printed with a usage error holds each synopsis of --help;
- docs/cli.md's first code block is the same synopsis;
- the man page's SYNOPSIS has the same synopsis (options, their values and choices, in the
  same order), its OPTIONS or COMMANDS name every option and subcommand, and its template
  paragraph every kind and preset of --help;
- the bash completion offers every option of the subcommand (and none it does not take),
  exactly the choices of each option of choices, every subcommand after `kinetostat`, and
  every kind and preset after `template`.
Prints one line per problem and the verdict "check_options: ok" or "check_options: N
problems"; exits 1 on any problem.
"""
import os
import re
import subprocess
import sys
import tempfile

TOKEN = re.compile(r"(\[)?(--?[A-Za-z][A-Za-z-]*)(?: ([^\s\].]+))?\]?(\.\.\.)?")


def parse_synopsis(lines):
    """Commands from synopsis lines: {name: [(option, value, required, repeated)]};
    the run of a deck is ""."""
    commands = {}
    current = None
    for line in lines:
        text = line.strip()
        if not text:
            continue
        if text.startswith("kinetostat"):
            words = text.split()
            name = ""
            rest = words[1:]
            if rest and re.fullmatch(r"[a-z]+", rest[0]):
                name, rest = rest[0], rest[1:]
            if rest and rest[0].startswith("--help"):
                current = None
                continue
            # the operands: the words before the first option
            while rest and not rest[0].lstrip("[").startswith("-") or (rest and rest[0] == "-"):
                rest = rest[1:]
            current = commands.setdefault(name, [])
            text = " ".join(rest)
        elif current is None:
            continue
        for m in TOKEN.finditer(text):
            current.append((m.group(2), m.group(3) or "", m.group(1) is None, bool(m.group(4))))
    return commands


def help_facts(binary):
    """The synopsis lines, kinds, presets of --help, and the usage line."""
    out = subprocess.run([binary, "--help"], capture_output=True, text=True, check=True).stdout.splitlines()
    start = next(i for i, l in enumerate(out) if l.startswith("  kinetostat"))
    end = next(i for i in range(start, len(out)) if not out[i].strip())
    synopsis = out[start:end]

    def listed(prefix):
        line = next((l for l in out if l.startswith(prefix)), "")
        return [w.strip() for w in line[len(prefix):].split(",") if w.strip()]

    usage = subprocess.run([binary], capture_output=True, text=True).stderr.splitlines()
    usage = next((l for l in usage if l.startswith("usage: ")), "")
    return synopsis, listed("Kinds: "), listed("Presets (template): "), usage


def one_line(lines):
    """A command's synopsis lines as one line."""
    return " ".join(l.strip() for l in lines)


def man_text(man):
    """The man page rendered as plain ASCII, no hyphenation, lines not wrapped."""
    env = dict(os.environ, GROFF_NO_SGR="1")
    text = subprocess.run(["groff", "-man", "-Tascii", "-rHY=0", "-rLL=400n", "-P", "-cbou", man],
                          capture_output=True, text=True, env=env, check=True).stdout
    return re.sub(".\b", "", text)


def section(text, title):
    m = re.search(r"^" + title + r"\n(.*?)(?=^[A-Z][A-Z ]+\n)", text, re.S | re.M)
    return m.group(1) if m else ""


def complete(completion, words, cwd):
    """COMPREPLY of the completion function for the words (the last is being completed)."""
    script = ('source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _kinetostat; '
              'printf "%s\\n" "${COMPREPLY[@]}"')
    r = subprocess.run(["bash", "-c", script, "_", os.path.abspath(completion)] + words,
                       capture_output=True, text=True, cwd=cwd)
    return {w for w in r.stdout.splitlines() if w}


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    binary = os.path.abspath(argv[1])
    completion, man, docs = "completions/kinetostat.bash", "man/kinetostat.1", "docs/cli.md"
    args = argv[2:]
    while args:
        if args[0] == "--completion":
            completion, args = args[1], args[2:]
        elif args[0] == "--man":
            man, args = args[1], args[2:]
        elif args[0] == "--docs":
            docs, args = args[1], args[2:]
        else:
            print(f"check_options: unknown argument {args[0]}", file=sys.stderr)
            return 2
    problems = []
    synopsis, kinds, presets, usage = help_facts(binary)
    commands = parse_synopsis(synopsis)
    if len(commands) < 7 or "" not in commands or not kinds or not presets:
        problems.append(f"--help: cannot read its synopsis or kinds ({sorted(commands)}, {kinds}, {presets})")

    # the usage line holds every synopsis of --help
    blocks, block = [], []
    for line in synopsis:
        if line.startswith("  kinetostat") and block:
            blocks.append(block)
            block = []
        block.append(line)
    blocks.append(block)
    for b in blocks:
        if one_line(b) not in usage:
            problems.append(f"usage line: lacks '{one_line(b)}'")

    # option names of the table: long and short (from --help's description lines)
    help_text = subprocess.run([binary, "--help"], capture_output=True, text=True).stdout
    shorts = dict(re.findall(r"(?:^|\s)(-[a-zA-Z])(?: [A-Z]+)?, (--[a-z-]+)", help_text, re.M))
    longs = {v: k for k, v in shorts.items()}

    # the docs' synopsis
    if docs:
        text = open(docs, encoding="utf-8").read()
        block = re.search(r"^```\n(.*?)^```", text, re.S | re.M)
        if not block or parse_synopsis(block.group(1).splitlines()) != commands:
            problems.append(f"{docs}: its first code block is not --help's synopsis")

    # the man page
    if man:
        text = man_text(man)
        man_commands = parse_synopsis(section(text, "SYNOPSIS").splitlines())
        for name, options in commands.items():
            label = f"kinetostat {name}".strip()
            if name not in man_commands:
                problems.append(f"man: SYNOPSIS lacks '{label}'")
                continue
            if man_commands[name] != options:
                want = [o[0] + (" " + o[1] if o[1] else "") for o in options]
                got = [o[0] + (" " + o[1] if o[1] else "") for o in man_commands[name]]
                missing = [w for w in want if w not in got]
                extra = [g for g in got if g not in want]
                problems.append(f"man: SYNOPSIS of '{label}' differs from --help: lacks {missing}, "
                                f"has besides {extra} (order and brackets must match too)")
        for name in man_commands:
            if name not in commands:
                problems.append(f"man: SYNOPSIS has 'kinetostat {name}', which --help does not")
        described = section(text, "OPTIONS") + section(text, "COMMANDS")
        every = {o[0] for opts in commands.values() for o in opts} | {"--help", "--version"}
        for option in sorted(every):
            if not re.search(r"(^|[\s,])" + re.escape(option) + r"\b", described):
                problems.append(f"man: OPTIONS and COMMANDS do not describe {option}")
        for name in commands:
            if name and not re.search(r"^ +" + name + r"\b", section(text, "COMMANDS"), re.M):
                problems.append(f"man: COMMANDS lacks {name}")
        template = re.search(r"template KIND\n(.*?)(?=\n {7}\S|\Z)", section(text, "COMMANDS"), re.S)
        template = template.group(1) if template else ""
        for kind in kinds + presets:
            if not re.search(r"\b" + re.escape(kind) + r"\b", template):
                problems.append(f"man: the template paragraph lacks the kind {kind}")

    # the completion
    if completion:
        with tempfile.TemporaryDirectory() as empty:
            offered = complete(completion, ["kinetostat", ""], empty)
            for name in commands:
                if name and name not in offered:
                    problems.append(f"completion: 'kinetostat ' offers {sorted(offered)}, lacks the subcommand {name}")
            offered = complete(completion, ["kinetostat", "template", ""], empty)
            for kind in kinds + presets:
                if kind not in offered:
                    problems.append(f"completion: 'kinetostat template ' lacks the kind {kind}")
            for kind in offered - set(kinds + presets):
                problems.append(f"completion: 'kinetostat template ' offers {kind}, which --help does not list")
            for name, options in commands.items():
                before = ["kinetostat"] + ([name, "x"] if name else ["x.nml"])
                label = " ".join(before)
                want = set()
                for option, _, _, _ in options:
                    want.add(option)
                    if option in shorts:
                        want.add(shorts[option])
                    if option in longs:
                        want.add(longs[option])
                offered = complete(completion, before + ["-"], empty)
                for option in sorted(want - offered):
                    problems.append(f"completion: '{label} -' lacks {option}")
                for option in sorted(offered - want - {"--help", "-h", "--version", "-V"}):
                    problems.append(f"completion: '{label} -' offers {option}, which '{name or 'DECK'}' does not take")
                for option, value, _, _ in options:
                    if "|" not in value:
                        continue
                    offered = complete(completion, before + [option, ""], empty)
                    choices = set(value.split("|"))
                    if offered != choices:
                        problems.append(f"completion: '{label} {option} ' offers {sorted(offered)}, "
                                        f"--help says {sorted(choices)}")

    for p in problems:
        print("check_options: " + p)
    print("check_options: ok" if not problems else f"check_options: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
