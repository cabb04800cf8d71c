"""check_commands.py SRC TOOLS_DIR: every command line of README.md's and docs/*.md's code blocks
runs as written, or is marked as needing an optional part.

A command line: a line of a ```sh block (each must be a command of a known program), a line of
an untagged block that starts with one (the other lines there are output or synopsis text), or
a `code span` in the text that is one with an argument; `\\` continuations joined, `# comments` dropped, `VAR=value` and `nice -n N` prefixes and a
`python3` before a script looked through. For each:
- the program exists and is executable as written (a script run directly needs its run bit and
  a #! line; `python3 SCRIPT` needs neither);
- every option it passes is one the program accepts, checked against the program's own
  --help (never starting work): farm.py's texrender options against texrender --help,
  scripts/test.sh's against its own --help (its options, then lit's, to which it passes the
  others), test-asan.sh's against lit's (it passes its arguments on);
- cheap commands run for real, as written, in a scratch folder whose entries link to the
  repository's (texcc on an input that exists: a second or less);
- a program that needs an optional part that is missing (Ray, bench's matplotlib) is reported as
  such, its existence still checked.
Prints one line per command and a summary; exits 1 if any command fails.
"""
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

SRC, TOOLS = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
VENV_PY = os.path.join(SRC, ".venv", "bin", "python")
TOOL_NAMES = ("texcc", "texrender", "texcc-eval", "texcc-graph")


def venv_has(module):
    return subprocess.run([VENV_PY, "-c", "import " + module], capture_output=True).returncode == 0


# How each program the docs run is checked. "help": the argv (relative to SRC) that prints its
# options, SUB standing for the command's first argument (a subcommand); "options": the options
# it takes when it has no --help; "passthrough": the program that gets the options it does not
# know; "needs": (module, part) an optional part in .venv; "run": cheap enough to run for real.
SUB = object()
PROGRAMS = {
    "scripts/main.sh": {"options": []},
    "scripts/setup.sh": {"options": []},
    "scripts/build.sh": {"options": []},
    "scripts/test.sh": {"help": ["scripts/test.sh", "--help"]},
    "scripts/test-asan.sh": {"help": [".venv/bin/lit", "--help"]},
    "scripts/farm.py": {"help": ["scripts/farm.py", SUB, "--help"], "passthrough": "texrender"},
    "scripts/blender_export.py": {"help": ["scripts/blender_export.py", "--help"]},
    "scripts/make_scenes.py": {"help": ["scripts/make_scenes.py", "--help"]},
    "bench/run": {"help": [".venv/bin/python", "bench/bench.py", "--help"],
                  "needs": ("matplotlib", "bench/requirements.txt, which bench/run installs")},
    "bench/fuzz": {"help": ["bench/fuzz", "--help"]},
    ".venv/bin/ray": {"help": [".venv/bin/ray", SUB, "--help"],
                      "needs": ("ray", "Ray, scripts/requirements-farm.txt")},
    "ninja": {"external": True},
    # Blender itself (the exporter also runs inside it): optional; the script it runs must exist.
    "blender": {"external": True, "optional": "Blender", "scripts_after": "--python"},
}
for name in TOOL_NAMES:
    PROGRAMS["build/bin/" + name] = {"help": ["build/bin/" + name, "--help"], "run": True}
# texcc's hidden options (--no-checks, for measurements) are documented too.
PROGRAMS["build/bin/texcc"]["help"] = ["build/bin/texcc", "--help-hidden"]


def code_lines(path):
    """(line number, text, in a sh block) of every code-block line, continuations joined."""
    out, tag, pending, start = [], None, "", 0
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            fence = re.match(r"\s*```(\S*)", line)
            if fence:
                tag = fence.group(1) if tag is None else None
                continue
            if tag not in ("", "sh", "bash", "shell"):
                continue
            text = line.rstrip("\n")
            if not pending:
                start = number
            if text.rstrip().endswith("\\"):
                pending += text.rstrip()[:-1] + " "
                continue
            out.append((start, pending + text, tag != ""))
            pending = ""
    return out


def inline_commands(path):
    """(line number, text) of every `code span` outside code blocks that is a command line of a
    known program with at least one argument (`texcc --list-nodes`, `scripts/farm.py stitch
    ...`)."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    blocks = [(m.start(), m.end()) for m in re.finditer(r"```.*?```", text, flags=re.S)]
    out = []
    for m in re.finditer(r"`([^`\n]+)`", text):
        if any(a <= m.start() < b for a, b in blocks) or " " not in m.group(1).strip():
            continue
        if split_command(m.group(1)):
            out.append((text.count("\n", 0, m.start()) + 1, m.group(1), False))
    return out


def program_key(word):
    """The PROGRAMS key of a command's first word, or None."""
    word = word[2:] if word.startswith("./") else word
    if word in TOOL_NAMES:
        return "build/bin/" + word
    return word if word in PROGRAMS else None


def split_command(text):
    """(program key, tokens after it, looked through python3) or None if not a command."""
    try:
        # A comment starts at a word's start only (frame.####.exr is no comment).
        tokens = shlex.split(re.sub(r"(^|\s)#.*$", "", text))
    except ValueError:
        return None
    while tokens and re.match(r"^[A-Z_][A-Z0-9_]*=", tokens[0]):
        tokens = tokens[1:]
    if tokens[:1] == ["nice"]:
        tokens = tokens[3:] if tokens[1:2] == ["-n"] else tokens[1:]
    via_python = tokens[:1] == ["python3"]
    if via_python:
        tokens = tokens[1:]
    if not tokens:
        return None
    key = program_key(tokens[0])
    return (key, tokens, via_python) if key else None


def options_of(args):
    """The options a command passes: '--name' and '-x' words (synopsis brackets stripped)."""
    found = []
    for arg in args:
        arg = arg.strip("[]()")
        m = re.match(r"^(--?[A-Za-z][\w-]*)", arg)
        if m and arg != "-":
            found.append(m.group(1))
    return found


_HELP = {}


def help_text(argv):
    """(exit status, output) of a --help run; a .py script runs under .venv's Python (whether
    it can run by itself is check_executable's question)."""
    key = tuple(argv)
    if key not in _HELP:
        first = os.path.join(SRC, argv[0]) if "/" in argv[0] else argv[0]
        command = ([VENV_PY, first] if first.endswith(".py") else [first]) + argv[1:]
        try:
            r = subprocess.run(command, cwd=SRC, capture_output=True, text=True, timeout=60)
            _HELP[key] = (r.returncode, r.stdout + r.stderr)
        except (OSError, subprocess.TimeoutExpired) as e:
            _HELP[key] = (-1, str(e))
    return _HELP[key]


def accepts(text, option):
    return re.search(r"(?<![\w-])%s(?![\w-])" % re.escape(option), text) is not None


def check_executable(key, tokens, via_python):
    path = os.path.join(TOOLS, os.path.basename(key)) if key.startswith("build/bin/") \
        else os.path.join(SRC, key)
    if not os.path.isfile(path):
        return "%s does not exist" % key
    if via_python:
        return None
    if not os.access(path, os.X_OK):
        return "%s is not executable (Permission denied: git update-index --chmod=+x %s)" % (
            key, key)
    if not key.startswith("build/bin/"):
        with open(path, "rb") as f:
            if f.read(2) != b"#!":
                return "%s has no #! line" % key
    return None


def check_options(key, spec, tokens):
    """None, or what is wrong with the options; also how they were checked (text)."""
    args = tokens[1:]
    options = options_of(args)
    if spec.get("external"):
        return None, "external program"
    if "help" not in spec:
        bad = [o for o in options if o not in spec["options"]]
        return ("takes no option %s" % ", ".join(bad) if bad else None), "takes no options"
    argv = [a if a is not SUB else (args[0] if args else "") for a in spec["help"]]
    argv = [os.path.join(TOOLS, os.path.basename(a)) if a.startswith("build/bin/") else a
            for a in argv]
    status, text = help_text(argv)
    if status != 0:
        return "%s exited %d: %s" % (" ".join(argv), status, text.strip()[-300:]), ""
    unknown = [o for o in options if o not in ("--help", "-h") and not accepts(text, o)]
    checked = "options against `%s`" % " ".join(os.path.basename(a) if a.startswith("/") else a
                                                 for a in argv)
    if spec.get("passthrough") and unknown:
        status, other = help_text([os.path.join(TOOLS, spec["passthrough"]), "--help"])
        unknown = [o for o in unknown if not accepts(other, o)]
        checked += " and %s --help" % spec["passthrough"]
    if unknown:
        return "option%s %s not accepted (%s)" % ("s" if len(unknown) > 1 else "",
                                                  ", ".join(unknown), checked), checked
    return None, checked


def runnable(key, tokens):
    """A cheap command whose inputs exist: texcc with an output folder and every input file
    present (not a fragment such as `texcc --mode=shape`)."""
    if key != "build/bin/texcc" or "-o" not in tokens:
        return False
    args, k = tokens[1:], 0
    while k < len(args):
        if args[k] in ("-o", "--graph") or not args[k].startswith("-"):
            if args[k] == "-o":
                k += 2
                continue
            path = args[k + 1] if args[k] == "--graph" else args[k]
            if re.search(r"[<>\[\]|]", path) or not os.path.exists(os.path.join(SRC, path)):
                return False
            k += 2 if args[k] == "--graph" else 1
            continue
        k += 1
    return True


def run_for_real(tokens, scratch):
    argv = [os.path.join(TOOLS, os.path.basename(tokens[0]))] + tokens[1:]
    r = subprocess.run(argv, cwd=scratch, capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        return "exited %d: %s" % (r.returncode, (r.stderr or r.stdout).strip()[-300:])
    return None


def main():
    files = [os.path.join(SRC, "README.md")] + sorted(glob.glob(os.path.join(SRC, "docs",
                                                                            "*.md")))
    scratch = tempfile.mkdtemp(prefix="docs-commands-")
    for entry in os.listdir(SRC):
        if entry not in ("out", ".git"):
            os.symlink(os.path.join(SRC, entry), os.path.join(scratch, entry))
    failed = total = 0
    try:
        for path in files:
            rel = os.path.relpath(path, SRC)
            for number, text, in_sh in code_lines(path) + inline_commands(path):
                if not text.strip() or text.strip().startswith("#"):
                    continue
                found = split_command(text)
                where = "%s:%d" % (rel, number)
                if found is None:
                    if in_sh:
                        failed += 1
                        print("FAIL %s: `%s`: not a command of a program this test knows "
                              "(add it to PROGRAMS)" % (where, text.strip()))
                    continue
                key, tokens, via_python = found
                total += 1
                spec = PROGRAMS[key]
                problem = check_executable(key, tokens, via_python) \
                    if not spec.get("external") else \
                    (None if shutil.which(key) else "%s is not on PATH" % key)
                after = spec.get("scripts_after")
                if after in tokens and tokens.index(after) + 1 < len(tokens):
                    script = tokens[tokens.index(after) + 1]
                    if not os.path.isfile(os.path.join(SRC, script)):
                        problem = "%s %s: no such file" % (after, script)
                    elif problem and spec.get("optional"):
                        print("OPTIONAL %s: %s: needs %s (not installed); %s exists"
                              % (where, key, spec["optional"], script))
                        continue
                how = ""
                if problem is None and spec.get("needs") and not venv_has(spec["needs"][0]):
                    print("OPTIONAL %s: %s: exists; needs %s (not installed): options not "
                          "checked" % (where, key, spec["needs"][1]))
                    continue
                if problem is None:
                    problem, how = check_options(key, spec, tokens)
                if problem is None and spec.get("run") and runnable(key, tokens):
                    problem = run_for_real(tokens, scratch)
                    how += "; ran as written"
                if problem:
                    failed += 1
                    line = "FAIL %s: `%s`: %s" % (where, " ".join(tokens), problem)
                    print(line)
                    sys.stderr.write(line + "\n")  # shown by lit when stdout is a file
                else:
                    print("OK %s: %s (%s)" % (where, key, how))
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    print("%d command lines, %d failed" % (total, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
