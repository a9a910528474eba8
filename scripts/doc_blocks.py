#!/usr/bin/env python3
# SPDX-License-Identifier: BSL-1.0
"""The docs' code blocks as tests (tests/docs/CMakeLists.txt registers them with ctest).

Every ```cpp and ```c block in README.md and docs/*.md is compiled, and run; a program whose output the doc
shows is run and its output compared. A ```gnuplot block runs on the files the doc's programs wrote. The
convention, an HTML comment on the line before the fence (invisible on GitHub), is documented in
docs/design.md ("Docs that are tested"):

    <!-- doc-test: fragment, state=std::array<float, 3>, check=r.status == odestep::status::ok -->
    <!-- doc-test: program, output=block -->
    <!-- doc-test: skip (why it cannot compile) -->

A block without a comment is a program if it defines `int main(`, else a fragment with the defaults. A
```sh block runs only when its comment says `run`: in the folder of the doc's program before it (after that
program, whose `file=NAME` option saves its source there as NAME), with $ODESTEP the repository's root;
`requires=tool ...` skips it (ctest: skipped) where a tool is missing.

Subcommands:
  generate ROOT OUT       write the translation units and the manifest OUT/docs.cmake (only files whose
                          contents changed are rewritten, so an unchanged doc recompiles nothing)
  run EXE EXPECTED DIR [SOURCE]  run EXE in DIR (created; SOURCE copied into it) and compare its stdout with
                          the file EXPECTED
  shell SCRIPT EXPECTED DIR ROOT [TOOL...]  run SCRIPT with bash in DIR, ODESTEP=ROOT; exit 77 if a TOOL is
                          missing
  gnuplot SCRIPT DIR      run gnuplot on SCRIPT in DIR; exit 77 (ctest: skipped) without gnuplot
  check ROOT              the convention (every skip has a reason, every option is known, same-as files
                          match) and the cited paths: every repository path README.md and docs/*.md name
                          exists
"""
import glob
import os
import re
import shutil
import subprocess
import sys

DOCS = ["README.md", "docs/*.md"]
COMPILED = {"cpp": "cpp", "c++": "cpp", "c": "c"}
OPTIONS = {"fragment", "program", "skip", "scope", "state", "check", "include", "output", "same-as", "no-run",
           "file", "run", "requires"}
SHELLS = {"sh", "bash"}
DEFAULT_STATE = "std::array<double, 2>"
FENCE = re.compile(r"^(```+)\s*([\w+-]*)\s*$")
ANNOTATION = re.compile(r"^<!--\s*doc-test:\s*(.*?)\s*-->\s*$")


class Block:
    def __init__(self, doc, line, lang, text, annotation, after):
        self.doc, self.line, self.lang, self.text = doc, line, lang, text
        self.annotation = annotation  # the comment's text, or None
        self.after = after  # the doc's text from the closing fence to the next fence
        self.options, self.errors = parse_options(annotation)

    def kind(self):
        if "skip" in self.options:
            return "skip"
        if "program" in self.options:
            return "program"
        if "fragment" in self.options:
            return "fragment"
        return "program" if re.search(r"^\s*int\s+main\s*\(", self.text, re.M) else "fragment"


def parse_options(annotation):
    """'fragment, state=std::array<double, 3>, check=a, b' -> {fragment: '', state: ..., check: 'a, b'}.
    A comma splits options only before a known option name, so values may hold commas."""
    options, errors = {}, []
    if annotation is None:
        return options, errors
    skip = re.match(r"^skip\b\s*(.*)$", annotation)
    if skip:
        reason = skip.group(1).strip()
        if not re.match(r"^\(.*\S.*\)$", reason):
            errors.append("a skip needs its reason in parentheses: skip (why)")
        options["skip"] = reason.strip("() ")
        return options, errors
    names = "|".join(re.escape(o) for o in sorted(OPTIONS, key=len, reverse=True))
    parts = re.split(r",\s*(?=(?:%s)\b)" % names, annotation)
    for part in parts:
        m = re.match(r"^([\w-]+)\s*(?:=\s*(.*))?$", part.strip(), re.S)
        if not m or m.group(1) not in OPTIONS:
            errors.append("unknown option %r (known: %s)" % (part.strip(), ", ".join(sorted(OPTIONS))))
            continue
        options[m.group(1)] = (m.group(2) or "").strip()
    return options, errors


def doc_files(root):
    files = []
    for pattern in DOCS:
        files += sorted(glob.glob(os.path.join(root, pattern)))
    return [os.path.relpath(f, root) for f in files]


def blocks_of(root, doc):
    with open(os.path.join(root, doc), encoding="utf-8") as stream:
        lines = stream.read().split("\n")
    blocks, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        fence, lang, start = m.group(1), m.group(2).lower(), i
        j = i + 1
        while j < len(lines) and lines[j].rstrip() != fence:
            j += 1
        annotation = None
        k = start - 1
        while k >= 0 and lines[k].strip() == "":
            k -= 1
        if k >= 0:
            a = ANNOTATION.match(lines[k].strip())
            if a:
                annotation = a.group(1)
        k = j + 1
        while k < len(lines) and not FENCE.match(lines[k]):
            k += 1
        blocks.append(Block(doc, start + 2, lang, "\n".join(lines[start + 1:j]), annotation,
                            "\n".join(lines[j + 1:k])))
        i = j + 1
    return blocks


def expected_output(block, blocks):
    """The output a program's doc shows: output=block, the next bare fenced block; output=inline, the first
    code span after 'prints'."""
    how = block.options.get("output")
    if how is None:
        return None
    if how == "block":
        later = [b for b in blocks if b.line > block.line and b.lang == ""]
        return later[0].text + "\n" if later else None
    if how == "inline":
        m = re.search(r"prints\s+`([^`]*)`", block.after)
        return m.group(1) + "\n" if m else None
    return None


def name_of(doc):
    return re.sub(r"[^\w]", "_", doc.replace(".md", ""))


def write_if_changed(path, text):
    if os.path.exists(path):
        with open(path, encoding="utf-8") as stream:
            if stream.read() == text:
                return
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as stream:
        stream.write(text)


def split_includes(text):
    """The block's #include lines (hoisted to the top of the translation unit) and its text with each such
    line left empty, so that #line keeps pointing at the doc's lines."""
    includes, body = [], []
    for line in text.split("\n"):
        if line.lstrip().startswith("#include"):
            includes.append(line.strip())
            body.append("")
        else:
            body.append(line)
    return includes, "\n".join(body)


def fragments_unit(root, doc, fragments):
    includes = ["#include <odestep/odestep.hpp>", '#include "doc_prelude.hpp"']
    for b in fragments:
        for extra in b.options.get("include", "").split():
            includes.append("#include %s" % extra)
        includes += split_includes(b.text)[0]
    unique = list(dict.fromkeys(includes))
    out = ["// Generated by scripts/doc_blocks.py from %s: do not edit." % doc, ""] + unique + [""]
    calls = []
    path = os.path.join(root, doc).replace("\\", "/")
    for b in fragments:
        body = split_includes(b.text)[1]
        ns = "doc_block_%d" % b.line
        if b.options.get("scope") == "namespace":
            out += ["namespace %s {" % ns, '#line %d "%s"' % (b.line, path), body, "}  // namespace " + ns, ""]
            continue
        state = b.options.get("state") or DEFAULT_STATE
        check = b.options.get("check")
        out += ["namespace %s {" % ns, "struct block : doc_prelude::names<%s> {" % state, "    bool run() {",
                '#line %d "%s"' % (b.line, path), body,
                "        return %s;" % (("static_cast<bool>(%s)" % check) if check else "true"),
                "    }", "};", "}  // namespace " + ns, ""]
        if "no-run" not in b.options:
            calls.append((b.line, ns))
    out += ["int main() {", "    int failures = 0;"]
    for line, ns in calls:
        out += ["    if (!%s::block{}.run()) {" % ns,
                '        std::printf("%s:%d: the fragment\'s check failed\\n");' % (doc, line), "        ++failures;",
                "    }"]
    out += ['    std::printf("%s: %d fragment(s) run, %%d failed\\n", failures);' % (doc, len(calls)),
            "    return failures == 0 ? 0 : 1;", "}", ""]
    return "\n".join(out)


def program_unit(root, block):
    path = os.path.join(root, block.doc).replace("\\", "/")
    return "// Generated by scripts/doc_blocks.py from %s: do not edit.\n#line %d \"%s\"\n%s\n" % (
        block.doc, block.line, path, block.text)


def generate(root, out):
    manifest = ["# Generated by scripts/doc_blocks.py: the docs' code blocks as tests.", "set(doc_fragment_units)",
                "set(doc_programs)", "set(doc_gnuplots)", "set(doc_shells)"]
    for doc in doc_files(root):
        blocks = blocks_of(root, doc)
        name = name_of(doc)
        fragments = [b for b in blocks if b.lang == "cpp" or b.lang == "c++"]
        fragments = [b for b in fragments if b.kind() == "fragment"]
        if fragments:
            unit = os.path.join(out, name, "fragments.cpp")
            write_if_changed(unit, fragments_unit(root, doc, fragments))
            manifest.append('list(APPEND doc_fragment_units "%s|%s")' % (name, unit))
        last_program = None
        for b in blocks:
            lang = COMPILED.get(b.lang)
            if lang and b.kind() == "program":
                test = "%s_line%d" % (name, b.line)
                unit = os.path.join(out, name, "line%d.%s" % (b.line, lang))
                write_if_changed(unit, program_unit(root, b))
                expected = expected_output(b, blocks)
                expected_file = ""
                if expected is not None:
                    expected_file = os.path.join(out, name, "line%d.expected" % b.line)
                    write_if_changed(expected_file, expected)
                source = ""
                if b.options.get("file"):
                    source = os.path.join(out, name, "line%d" % b.line, b.options["file"])
                    write_if_changed(source, b.text + "\n")
                manifest.append('list(APPEND doc_programs "%s|%s|%s|%s|%s")' % (test, lang, unit, expected_file, source))
                last_program = test
            elif b.lang in SHELLS and "run" in b.options and "skip" not in b.options:
                script = os.path.join(out, name, "line%d.sh" % b.line)
                write_if_changed(script, b.text + "\n")
                expected = expected_output(b, blocks)
                expected_file = ""
                if expected is not None:
                    expected_file = os.path.join(out, name, "line%d.expected" % b.line)
                    write_if_changed(expected_file, expected)
                manifest.append('list(APPEND doc_shells "%s_line%d|%s|%s|%s|%s")' % (
                    name, b.line, script, expected_file, last_program or "", b.options.get("requires", "")))
            elif b.lang == "gnuplot" and "skip" not in b.options:
                script = os.path.join(out, name, "line%d.gp" % b.line)
                write_if_changed(script, b.text + "\n")
                manifest.append('list(APPEND doc_gnuplots "%s_line%d|%s|%s")' % (name, b.line, script,
                                                                                 last_program or ""))
    write_if_changed(os.path.join(out, "docs.cmake"), "\n".join(manifest) + "\n")
    return 0


def run(exe, expected_file, workdir, source=""):
    os.makedirs(workdir, exist_ok=True)
    if source:
        shutil.copy(source, workdir)
    result = subprocess.run([exe], cwd=workdir, stdout=subprocess.PIPE, timeout=60)
    return compare_output(exe, result, expected_file)


def shell(script, expected_file, workdir, root, tools):
    missing = [t for t in tools if shutil.which(t) is None]
    if missing:
        print("doc_blocks: %s missing: not run" % ", ".join(missing))
        return 77
    os.makedirs(workdir, exist_ok=True)
    env = dict(os.environ, ODESTEP=os.path.abspath(root))
    result = subprocess.run(["bash", "-euo", "pipefail", os.path.abspath(script)], cwd=workdir, stdout=subprocess.PIPE, env=env,
                            timeout=300)
    return compare_output(script, result, expected_file)


def compare_output(what, result, expected_file):
    output = result.stdout.decode("utf-8", "replace")
    sys.stdout.write(output)
    if result.returncode != 0:
        print("doc_blocks: %s exited with %d" % (what, result.returncode))
        return 1
    if expected_file:
        with open(expected_file, encoding="utf-8") as stream:
            expected = stream.read()
        if output != expected:
            print("doc_blocks: the output differs from the doc's:\n--- the doc\n%s--- the run\n%s" % (expected, output))
            return 1
    return 0


def gnuplot(script, workdir):
    if shutil.which("gnuplot") is None:
        print("doc_blocks: gnuplot is missing: not run")
        return 77
    os.makedirs(workdir, exist_ok=True)
    result = subprocess.run(["gnuplot", script], cwd=workdir, stderr=subprocess.PIPE, timeout=60)
    errors = result.stderr.decode("utf-8", "replace")
    sys.stdout.write(errors)
    # gnuplot reports a missing file or column as a warning and still exits 0: any message fails.
    return 1 if result.returncode != 0 or errors.strip() else 0


# A cited path: starts with one of the repository's top-level folders or is one of its top-level files,
# or is an include spelling <odestep/...> (include/odestep/...) or host/... (include/odestep/host/...).
TOP = r"(?:include|src|tests|examples|scripts|docs|toolchains|bench|cmake|\.ci)/"
TOP_FILES = r"(?:README\.md|CHANGELOG\.md|CMakeLists\.txt|CMakePresets\.json|LICENSE)"
PATH = re.compile(r"(?<![\w./$-])((?:%s[\w./+*-]*)|(?:odestep/[\w./-]+\.(?:hpp|h))|(?:%s)(?![\w.]))" % (TOP, TOP_FILES))
LINK = re.compile(r"\]\(([^)\s]+)\)")


def cited_paths(root, doc):
    missing = []
    with open(os.path.join(root, doc), encoding="utf-8") as stream:
        lines = stream.read().split("\n")
    base = os.path.dirname(os.path.join(root, doc))
    for number, line in enumerate(lines, 1):
        for target in LINK.findall(line):
            target = target.split("#")[0]
            if not target or re.match(r"^[a-z]+:", target):
                continue
            if not os.path.exists(os.path.join(base, target)):
                missing.append((number, target))
        for m in PATH.finditer(line):
            path = m.group(1).rstrip(".,:;)")
            # A pattern (tests/*/x, docs/gallery/*.png, tests/fuzz/known/<target>/) names no one path.
            if "*" in path or "..." in path or line[m.end():m.end() + 1] == "<":
                continue
            candidates = [os.path.join(root, path), os.path.join(root, "include", path)]
            if not any(os.path.exists(c) for c in candidates):
                missing.append((number, path))
        for m in re.finditer(r"(?<![\w/])(host/[\w.]+\.hpp)", line):
            if not os.path.exists(os.path.join(root, "include/odestep", m.group(1))):
                missing.append((number, m.group(1)))
    return missing


def same_as(root, block):
    path = os.path.join(root, block.options["same-as"])
    if not os.path.exists(path):
        return "same-as: %s does not exist" % block.options["same-as"]
    with open(path, encoding="utf-8") as stream:
        text = stream.read()
    # The file's license line is the only difference allowed.
    text = re.sub(r"^(//|/\*) SPDX-License-Identifier: BSL-1\.0( \*/)?\n", "", text)
    if text.rstrip("\n") != block.text.rstrip("\n"):
        return "the block differs from %s" % block.options["same-as"]
    return None


def check(root):
    problems = []
    skips = 0
    for doc in doc_files(root):
        blocks = blocks_of(root, doc)
        for b in blocks:
            where = "%s:%d" % (doc, b.line - 1)
            problems += ["%s: %s" % (where, e) for e in b.errors]
            if b.annotation is not None and b.lang not in COMPILED and b.lang != "gnuplot" and b.lang not in SHELLS:
                problems.append("%s: a doc-test comment on a ```%s block (only c, cpp, gnuplot and sh run)" % (where, b.lang))
            if b.lang in SHELLS and b.annotation is not None and "run" not in b.options and "skip" not in b.options:
                problems.append("%s: a doc-test comment on a ```%s block without `run`" % (where, b.lang))
            if "skip" in b.options:
                skips += 1
                print("%s: skipped: %s" % (where, b.options["skip"]))
            if "same-as" in b.options:
                diff = same_as(root, b)
                if diff:
                    problems.append("%s: %s" % (where, diff))
            if "output" in b.options:
                if b.options["output"] not in ("block", "inline"):
                    problems.append("%s: output=%s (block or inline)" % (where, b.options["output"]))
                elif expected_output(b, blocks) is None:
                    problems.append("%s: output=%s but the doc shows no output there" % (where, b.options["output"]))
            if COMPILED.get(b.lang) == "c" and b.kind() == "fragment":
                problems.append("%s: a C block must be a whole program (or skipped, with a reason)" % where)
        for number, path in sorted(set(cited_paths(root, doc))):
            problems.append("%s:%d: cites %s, which does not exist" % (doc, number, path))

    for p in problems:
        print(p)
    print("doc_blocks: %d problem(s), %d skipped block(s)" % (len(problems), skips))
    return 1 if problems else 0


def main(argv):
    if len(argv) == 4 and argv[1] == "generate":
        return generate(argv[2], argv[3])
    if len(argv) in (5, 6) and argv[1] == "run":
        return run(*argv[2:])
    if len(argv) >= 6 and argv[1] == "shell":
        return shell(argv[2], argv[3], argv[4], argv[5], argv[6:])
    if len(argv) == 4 and argv[1] == "gnuplot":
        return gnuplot(argv[2], argv[3])
    if len(argv) == 3 and argv[1] == "check":
        return check(argv[2])
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
