#!/usr/bin/python3
"""The self-test of scripts/mutate: its mutants (no build), then a run on a tiny CMake/GoogleTest project in a
temporary folder, where one mutant must be killed, one must survive and one listed as equivalent must not run, so
that the tool's verdicts can be seen to fail as well as pass."""
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts"))
from mutation.mutants import file_mutants, mask  # noqa: E402

CALC = """\
// A comment with a < b and 1 + 2 is not mutated.
#include "calc.h"
int saturate(int x) { return x > 100 ? 100 : x; }
int untested(int x) { return x * 3; }
const char* name() { return "a < b"; }
"""
TEST = """\
#include <gtest/gtest.h>
#include "calc.h"
TEST(Calc, SaturatesAboveAHundred) {
  EXPECT_EQ(saturate(150), 100);
  EXPECT_EQ(saturate(50), 50);
}
"""
CMAKE = """\
cmake_minimum_required(VERSION 3.25)
project(fixture CXX)
find_package(GTest REQUIRED)
add_library(calc STATIC src/calc.cpp)
target_include_directories(calc PUBLIC src)
add_executable(calc_tests tests/calc_test.cpp)
target_link_libraries(calc_tests PRIVATE calc GTest::gtest_main)
"""
FAILURES = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        FAILURES.append(what)


def mutants_are_found_only_in_code():
    keys = [m.key for m in file_mutants("src/calc.cpp", CALC)]
    check(all(not k.startswith("src/calc.cpp:1:") and not k.startswith("src/calc.cpp:5:") for k in keys),
          "nothing mutated in comments, includes or strings")
    check("src/calc.cpp:3: > → < (col 32)" in keys, "a comparison flipped")
    check("src/calc.cpp:3: 100 → 101 (col 34)" in keys, "a bound moved by one")
    check("src/calc.cpp:4: * → / (col 32)" in keys, "an arithmetic operator swapped")
    check(not file_mutants("a.cpp", "std::array<double, 3> a{};\nchar line[200];\n"), "template arguments and buffer sizes kept")
    check(mask('x = "a\\"b" + 1;') == 'x = "    " + 1;', "string literals masked, escapes and all")
    check(not file_mutants("a.cpp", 'f(path + ":" + why);\n'), "no - where a string is joined (it would not compile)")
    swapped = [m for m in file_mutants("a.cpp", "  if (a && !b) return true;\n")]
    check({m.desc for m in swapped} >= {"&& → || (col 9)", "a && !b → !(a && !b) (col 7)", "true → false (col 23)"},
          "&& swapped, the condition negated, the returned boolean flipped")


def run_on_fixture():
    with tempfile.TemporaryDirectory(prefix="mutate_test_") as tmp:
        fx = Path(tmp)
        (fx / "src").mkdir()
        (fx / "tests").mkdir()
        (fx / "scripts/mutation").mkdir(parents=True)
        (fx / "docs").mkdir()
        (fx / "src/calc.cpp").write_text(CALC)
        (fx / "src/calc.h").write_text("#pragma once\nint saturate(int x);\nint untested(int x);\n")
        (fx / "tests/calc_test.cpp").write_text(TEST)
        (fx / "CMakeLists.txt").write_text(CMAKE)
        (fx / "scripts/mutation/tests.txt").write_text("src calc_tests Calc.*\n")
        (fx / "docs/mutants-equivalent.txt").write_text(
            "src/calc.cpp:3: > → >= (col 32) — saturate(100) is 100 either way\n")
        subprocess.run(["git", "init", "-q"], cwd=fx, check=True)
        log = fx / "run.log"
        # One mutant the test kills, one in a function no test calls, and the equivalent one.
        cmd = [sys.executable, str(ROOT / "scripts/mutate"), "--root", str(fx), "src", "--out", str(log),
               "--grep", r"calc.cpp:3: > → (<|>=) |calc.cpp:4: \* → /", "--fail-under", "60", "--jobs", "2"]
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=900)
        out = done.stdout
        print(out, done.stderr)
        check("KILLED    src/calc.cpp:3: > → < (col 32)" in out, "the mutant the test catches is killed")
        check("SURVIVED  src/calc.cpp:4: * → / (col 32)" in out, "the mutant of untested code survives")
        check("1 listed as equivalent, 2 to run" in out and "> → >= (col 32)" not in out.split("to run")[1],
              "the equivalent mutant is counted, not run")
        check("kill rate 50.0 %" in out, "the kill rate is killed over killed and survived")
        check("tests run: calc_tests --gtest_filter='Calc.*'" in out, "a survivor names the tests run")
        check(done.returncode == 1, "--fail-under 60 fails a run at 50 %")
        check(log.exists() and "SURVIVED" in log.read_text(), "--out writes the run's log")
        check((fx / "src/calc.cpp").read_text() == CALC and (fx / "build-mutate/tree/src/calc.cpp").read_text() == CALC,
              "the sources are left as they were")


if __name__ == "__main__":
    mutants_are_found_only_in_code()
    if not FAILURES:
        run_on_fixture()
    sys.exit(1 if FAILURES else 0)
