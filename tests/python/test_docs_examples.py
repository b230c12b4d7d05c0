"""Runs the examples of README.md and docs/*.md: every example must run as written.

Convention (documented for writers in docs/BUILD_AND_TEST.md, "Examples in the docs are
tests"): the info string of a fenced code block says whether it is run.

  ```sh       run: bash -e -o pipefail, in a fresh empty directory
  ```cpp      run: a whole program, compiled (C++20, tritri and the arrangements library),
              then run in a fresh empty directory
  ```python   run: this interpreter (sys.executable; `import tritri` must work), in a fresh
              empty directory
  ```console  ```cpp-fragment  ```python-fragment  ```cmake  ```text  ``` (no tag)
              shown only, never run: commands that take minutes or change a checkout
              (console), code that is not a whole program (fragments), output, layouts

Any other tag fails test_fence_tags_are_known, so that a typo (```bash, ```c++) cannot
silently turn an example into text. The one exception: the README's first block (```sh,
scripts/main_job.sh and scripts/test_all.sh, which build and test everything) is not run;
test_readme_first_screen checks that it is exactly those two lines, first in the file
(CI relies on that), and that the README's first 40 lines hold it and one CLI, one C++
and one Python example of 5 to 10 lines.

Every run has exit status 0 within TIMEOUT seconds and sees this environment:
  PATH          TRITRI_BUILD_DIR/bin (default: build/bin: arrange, tritri-compare,
                make_test_meshes), then this interpreter's directory, then the inherited PATH
  TRITRI_ROOT   the repository root (e.g. for bench/ scripts)
C++ examples are compiled one of two ways:
  TRITRI_PREFIX set    each block is a target of one small CMake project against that
                       install prefix (find_package(tritri COMPONENTS arrangements), as
                       examples/cpp/CMakeLists.txt does; scripts/test_all.sh stage 3
                       installs build/ to such a prefix)
  else                 g++ -std=c++20 against the headers of the checkout and
                       TRITRI_BUILD_DIR/arrangements/libarrangements.a, with the flags of
                       the project's CMake (-ffp-contract=off, -frounding-math, CGAL with
                       TBB, gmpxx, mpfr, gmp, Eigen)
JOBS (default: the number of cores) of them compile at once. When neither is available
the C++ examples are skipped, unless the environment variable CI is set: in CI a missing
prerequisite fails. So are the sh examples without build/bin, and the Python examples when
this interpreter cannot import tritri.

Run: python -m pytest -q tests/python/test_docs_examples.py (from the venv of
scripts/test_python.sh: build-python/venv/bin/python).
"""
import os
import re
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("TRITRI_BUILD_DIR", REPO / "build"))
PREFIX = os.environ.get("TRITRI_PREFIX")
IN_CI = bool(os.environ.get("CI"))
JOBS = max(1, int(os.environ.get("JOBS") or os.cpu_count() or 1))  # C++ examples compiled at once
TIMEOUT = 120         # seconds per run, and per compilation
README_FIRST_SCREEN = 40
FIRST_BLOCK = ["scripts/main_job.sh   # main job: native vs tritri on the generated default meshes -> results/report/",
               "scripts/test_all.sh   # all tests: Release + sanitizer ctest, install/consumer/examples, Python"]

RUN = {"sh", "cpp", "python"}
SHOWN = {"", "console", "cpp-fragment", "python-fragment", "cmake", "text"}

FENCE = re.compile(r"^( {0,3})(`{3,}|~{3,})[ \t]*([^`\s]*)[^`]*$")


class Block:
    def __init__(self, path, line, end, tag, code):
        self.path, self.line, self.end, self.tag, self.code = path, line, end, tag, code

    @property
    def name(self):  # e.g. README.md:25-31
        return f"{self.path.relative_to(REPO)}:{self.line}-{self.end}"


def fenced_blocks(path):
    """The fenced code blocks of a Markdown file (CommonMark fences of ``` or ~~~, indented
    by at most 3 spaces; an unclosed fence runs to the end of the file), in order."""
    found, lines, i = [], path.read_text(encoding="utf-8").splitlines(), 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        indent, fence, tag = len(m.group(1)), m.group(2), m.group(3)
        close = re.compile(r"^ {0,3}" + re.escape(fence[0]) + "{" + str(len(fence)) + r",}[ \t]*$")
        j = i + 1
        while j < len(lines) and not close.match(lines[j]):
            j += 1
        body = [line[min(indent, len(line) - len(line.lstrip(" "))):] for line in lines[i + 1:j]]
        found.append(Block(path, i + 1, min(j, len(lines)) + 1, tag, "\n".join(body) + "\n"))
        i = j + 1
    return found


DOCS = [REPO / "README.md"] + sorted((REPO / "docs").glob("*.md"))
ALL_BLOCKS = [b for path in DOCS for b in fenced_blocks(path)]
README_BLOCKS = [b for b in ALL_BLOCKS if b.path.name == "README.md"]
EXAMPLES = [b for b in ALL_BLOCKS if b.tag in RUN and b is not README_BLOCKS[0]]  # not the two scripts


def blocks(tag):
    return [b for b in EXAMPLES if b.tag == tag]


def params(tag):
    return [pytest.param(b, id=b.name) for b in blocks(tag)]


def unavailable(reason):
    """Skip outside CI; in CI a missing prerequisite is a failure."""
    if IN_CI:
        pytest.fail(f"{reason} (CI is set, so this fails instead of skipping)")
    pytest.skip(reason)


def environment():
    env = dict(os.environ, TRITRI_ROOT=str(REPO), PYTHONDONTWRITEBYTECODE="1")
    env["PATH"] = os.pathsep.join([str(BUILD / "bin"), str(Path(sys.executable).parent), env.get("PATH", "")])
    return env


def run(command, cwd, what, timeout=TIMEOUT):
    start = time.monotonic()
    try:
        p = subprocess.run(command, cwd=cwd, env=environment(), capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired as e:
        pytest.fail(f"{what}: still running after {timeout} s\n{e.stdout or ''}{e.stderr or ''}")
    assert p.returncode == 0, (f"{what}: exit status {p.returncode} after {time.monotonic() - start:.1f} s\n"
                               f"--- stdout\n{p.stdout}\n--- stderr\n{p.stderr}")
    return p


# --- the conventions ------------------------------------------------------------------------

def test_fence_tags_are_known():
    bad = [f"{b.name} ```{b.tag}" for b in ALL_BLOCKS if b.tag not in RUN | SHOWN]
    assert not bad, f"unknown code fence tags (run: {sorted(RUN)}; shown: {sorted(SHOWN - {''})}): {bad}"


def test_readme_first_screen():
    first = README_BLOCKS[0]
    assert first.line == 1 and first.tag == "sh", "README.md must start with the ```sh block of the two scripts"
    assert first.code.splitlines() == FIRST_BLOCK, "README.md's first block must be exactly the two scripts"
    screen = [b for b in README_BLOCKS[1:] if b.end <= README_FIRST_SCREEN]
    assert sorted(b.tag for b in screen) == ["cpp", "python", "sh"], \
        f"the README's first {README_FIRST_SCREEN} lines hold one CLI, one C++ and one Python example"
    for b in screen:
        assert 5 <= len(b.code.splitlines()) <= 10, f"{b.name}: a first-screen example has 5 to 10 lines"


def anchors(path):
    """GitHub's anchors of a Markdown file's headings: lower case, punctuation dropped, spaces
    to hyphens."""
    text = fence_free(path)
    return {re.sub(r"[^\w\- ]", "", h.strip().lower()).replace(" ", "-") for h in re.findall(r"^#+ (.*)$", text, re.M)}


def fence_free(path):
    lines = path.read_text(encoding="utf-8").splitlines()
    for b in fenced_blocks(path):
        lines[b.line - 1:b.end] = [""] * (b.end - b.line + 1)
    return "\n".join(lines)


def test_relative_links_resolve():
    broken = []
    for path in DOCS:
        for target in re.findall(r"\]\(([^)\s]+)\)", fence_free(path)):
            if re.match(r"[a-z]+:", target):
                continue
            file, _, anchor = target.partition("#")
            linked = path.parent / file if file else path
            if not linked.exists() or (anchor and linked.suffix == ".md" and anchor not in anchors(linked)):
                broken.append(f"{path.relative_to(REPO)}: {target}")
    assert not broken, f"links to missing files or headings: {broken}"


def test_there_are_examples():
    assert {b.tag for b in EXAMPLES} == RUN


# --- the runners ----------------------------------------------------------------------------

@pytest.mark.parametrize("block", params("sh"))
def test_sh_example(block, tmp_path):
    if not (BUILD / "bin" / "arrange").exists():
        unavailable(f"{BUILD / 'bin'} has no arrange (build the project first)")
    script = tmp_path / "example.sh"
    script.write_text(block.code)
    run(["bash", "-e", "-o", "pipefail", str(script)], tmp_path, block.name)


@pytest.fixture(scope="session")
def tritri_module(tmp_path_factory):
    """Whether this interpreter imports the installed tritri (outside the checkout, whose
    C++ folder tritri/ would otherwise pass for a namespace package)."""
    p = subprocess.run([sys.executable, "-c", "import tritri._tritri"], cwd=tmp_path_factory.mktemp("import"),
                       capture_output=True, text=True)
    return p.returncode == 0 or p.stderr


@pytest.mark.parametrize("block", params("python"))
def test_python_example(block, tmp_path, tritri_module):
    if tritri_module is not True:
        unavailable(f"{sys.executable} cannot import tritri (pip install ., or use build-python/venv): "
                    f"{tritri_module.strip().splitlines()[-1]}")
    script = tmp_path / "example.py"
    script.write_text(block.code)
    run([sys.executable, str(script)], tmp_path, block.name)


CMAKE_PROJECT = """cmake_minimum_required(VERSION 3.20)
project(docs_examples LANGUAGES CXX)
find_package(tritri 0.1 CONFIG REQUIRED COMPONENTS arrangements)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(CGAL REQUIRED)
find_package(TBB CONFIG REQUIRED)
file(GLOB examples ${CMAKE_SOURCE_DIR}/*.cpp)
foreach(source ${examples})
  get_filename_component(name ${source} NAME_WE)
  add_executable(${name} ${source})
  target_link_libraries(${name} PRIVATE tritri::arrangements Eigen3::Eigen)
endforeach()
"""


def cpp_name(block):
    return "example_" + re.sub(r"\W", "_", block.name)


@pytest.fixture(scope="session")
def cpp_programs(request, tmp_path_factory):
    """{block name: (executable, error message or None)} for the C++ examples this session
    runs, all compiled at once (JOBS in parallel); None when there is nothing to compile
    against."""
    selected = {item.callspec.params["block"].name for item in request.session.items
                if item.originalname == "test_cpp_example"}
    cpp, out = [b for b in blocks("cpp") if b.name in selected], tmp_path_factory.mktemp("cpp_examples")
    if PREFIX:  # one CMake project against the install prefix, one target per block
        (out / "CMakeLists.txt").write_text(CMAKE_PROJECT)
        for b in cpp:
            (out / f"{cpp_name(b)}.cpp").write_text(b.code)
        generator = ["-G", "Ninja"] if shutil.which("ninja") else []
        p = subprocess.run(["cmake", "-S", out, "-B", out / "build", *generator, "-DCMAKE_BUILD_TYPE=",
                            f"-DCMAKE_PREFIX_PATH={PREFIX}"], capture_output=True, text=True, timeout=TIMEOUT)
        if p.returncode != 0:
            return {b.name: (None, f"cmake against TRITRI_PREFIX={PREFIX} failed:\n{p.stdout}{p.stderr}") for b in cpp}
        subprocess.run(["cmake", "--build", out / "build", "-j", str(JOBS)], capture_output=True,
                       timeout=TIMEOUT * len(cpp))
        programs = {}
        for b in cpp:  # a target that did not build: build it alone for its own message
            exe = out / "build" / cpp_name(b)
            if not exe.exists():
                p = subprocess.run(["cmake", "--build", out / "build", "--target", cpp_name(b)],
                                   capture_output=True, text=True, timeout=TIMEOUT)
            programs[b.name] = (exe, None if exe.exists() else f"build failed:\n{p.stdout}{p.stderr}")
        return programs

    library = BUILD / "arrangements" / "libarrangements.a"
    if not library.exists() or not shutil.which("g++"):
        return None
    flags = ["-std=c++20", "-O0", "-ffp-contract=off", "-frounding-math", "-DCGAL_LINKED_WITH_TBB",
             "-DCGAL_USE_GMPXX=1", f"-I{REPO / 'tritri' / 'include'}", f"-I{REPO / 'arrangements' / 'include'}",
             "-isystem", "/usr/include/eigen3"]
    libs = [str(library), "-ltbb", "-lgmpxx", "-lmpfr", "-lgmp", "-pthread"]

    def compile(block):
        source, exe = out / f"{cpp_name(block)}.cpp", out / cpp_name(block)
        source.write_text(block.code)
        p = subprocess.run(["g++", *flags, source, "-o", exe, *libs], capture_output=True, text=True,
                           timeout=TIMEOUT)
        return block.name, (exe, None if p.returncode == 0 else f"g++ failed:\n{p.stdout}{p.stderr}")
    with ThreadPoolExecutor(max_workers=JOBS) as pool:
        return dict(pool.map(compile, cpp))


@pytest.mark.parametrize("block", params("cpp"))
def test_cpp_example(block, tmp_path, cpp_programs):
    if cpp_programs is None:
        unavailable(f"no TRITRI_PREFIX and no {BUILD / 'arrangements' / 'libarrangements.a'}: "
                    "cannot compile the C++ examples")
    exe, error = cpp_programs[block.name]
    assert error is None, f"{block.name}: {error}"
    run([str(exe)], tmp_path, block.name)
