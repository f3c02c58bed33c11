"""The mutants of a C++ source file: small semantic changes, one per mutant, found line by line.

Pure text work (no compiler): comments, string and character literals and preprocessor lines are masked first, so
that nothing inside them is mutated. Binary operators are recognised by the spaces clang-format puts around them
(`a < b`), which keeps template brackets (`std::array<int, 3>`), pointers and references out.
"""
import re
from dataclasses import dataclass


@dataclass(frozen=True)
class Mutant:
    path: str  # relative to the project's root
    line: int  # 1-based
    col: int  # 1-based column of the changed text
    old: str
    new: str
    kind: str

    @property
    def desc(self):
        """How the mutant is named in reports and in docs/mutants-equivalent.txt."""
        return f"{self.old} → {self.new} (col {self.col})"

    @property
    def key(self):
        return f"{self.path}:{self.line}: {self.desc}"

    def apply(self, text):
        """The file's text with this mutant in place."""
        lines = text.split("\n")
        row = lines[self.line - 1]
        start = self.col - 1
        assert row[start:start + len(self.old)] == self.old, f"{self.key}: the source changed under the mutant"
        lines[self.line - 1] = row[:start] + self.new + row[start + len(self.old):]
        return "\n".join(lines)


def mask(text):
    """The text with comments, literals and preprocessor lines blanked, columns and line breaks kept."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == "#" or (line_start and c in " \t" and text[i:].lstrip(" \t").startswith("#")):
            end = text.find("\n", i)
            end = n if end < 0 else end
            out.append(" " * (end - i))
            i = end
            continue
        if text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
            out.append(" " * (end - i))
            i = end
            continue
        if text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
            line_start = False
            continue
        raw = re.match(r'R"([^(\s]*)\(', text[i:i + 20])
        if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            end = text.find(")" + raw.group(1) + '"', i)
            end = n if end < 0 else end + len(raw.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
            continue
        if c in "\"'" and not (c == "'" and i > 0 and text[i - 1].isalnum()):  # 1'000'000 is a number
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            end = min(j + 1, n)
            out.append(c + " " * (end - i - 2) + c if end - i >= 2 else " ")
            i = end
            continue
        out.append(c)
        line_start = c == "\n" or (line_start and c in " \t")
        i += 1
    return "".join(out)


# Binary operators written with a space on each side; the longer spellings first.
_SWAPS = {
    "<": ["<=", ">"], "<=": ["<", ">"], ">": [">=", "<"], ">=": [">", "<"], "==": ["!="], "!=": ["=="],
    "+": ["-"], "-": ["+"], "*": ["/"], "/": ["*"], "+=": ["-="], "-=": ["+="], "*=": ["/="], "/=": ["*="],
    "&&": ["||"], "||": ["&&"],
}
_KINDS = {"<": "relational", "<=": "relational", ">": "relational", ">=": "relational", "==": "relational",
          "!=": "relational", "&&": "logical", "||": "logical"}
_BINARY = re.compile(r"(?<= )(<=|>=|==|!=|\+=|-=|\*=|/=|&&|\|\||<|>|\+|-|\*|/)(?= )")
# A minus in front of an operand, after an opening bracket, a comma, an operator or `return`.
_UNARY_MINUS = re.compile(r"(?:(?<=[(\[{,=?:!<>*/+])|(?<=return)) ?(-)(?=[\w(.])")
# An integer literal, not a part of a name, a float or a template argument (`block<3, 3>`).
_INTEGER = re.compile(r"(?<![\w.<])(?<![eE][-+])(\d+)([uUlLzZ]*)(?![\w.'>])")
_RETURN_BOOL = re.compile(r"\breturn (true|false);")
_IF = re.compile(r"\bif \(")


def _condition_end(line, open_at):
    """The index of the parenthesis closing the one at open_at, or -1 when it is on another line."""
    depth = 0
    for k in range(open_at, len(line)):
        if line[k] == "(":
            depth += 1
        elif line[k] == ")":
            depth -= 1
            if depth == 0:
                return k
    return -1


def line_mutants(path, number, code, original):
    """The mutants of one line: code is the masked line, original the line as written."""
    found = []

    def add(col0, old, new, kind):
        found.append(Mutant(path, number, col0 + 1, old, new, kind))

    for m in _BINARY.finditer(code):
        op = m.group(1)
        if op in ("<", ">") and re.search(r"\b(template|static_cast|reinterpret_cast|const_cast)\b", code):
            continue  # angle brackets of templates that happen to have spaces
        if op in ("+", "-") and (code[:m.start(1)].rstrip().endswith('"') or code[m.end(1):].lstrip().startswith('"')):
            continue  # a string being joined: `-` would not compile
        for new in _SWAPS[op]:
            add(m.start(1), op, new, _KINDS.get(op, "arithmetic"))
    for m in _UNARY_MINUS.finditer(code):
        if code[m.start(1):m.start(1) + 2] in ("--", "->", "-="):
            continue
        add(m.start(1), "-", "", "sign")
    for m in _INTEGER.finditer(code):
        value, suffix = int(m.group(1)), m.group(2)
        if code[m.start(1):m.start(1) + 2].lower() == "0x":
            continue
        if re.match(r"\w\[$", code[max(0, m.start() - 2):m.start()]) and re.match(r"\](;| =| {)", code[m.end():]):
            continue  # an array's size (`char line[200];`): a buffer one larger or smaller is no test's business
        add(m.start(1), m.group(0), f"{value + 1}{suffix}", "bound")
        if value > 0:
            add(m.start(1), m.group(0), f"{value - 1}{suffix}", "bound")
    for m in _RETURN_BOOL.finditer(code):
        flipped = "false" if m.group(1) == "true" else "true"
        add(m.start(1), m.group(1), flipped, "return")
    for m in _IF.finditer(code):
        if code[m.end():].startswith("constexpr"):
            continue
        open_at = m.end() - 1
        close_at = _condition_end(code, open_at)
        if close_at < 0 or ";" in code[open_at:close_at]:  # several lines, or an if with an initialiser
            continue
        cond = original[open_at + 1:close_at]
        add(open_at + 1, cond, f"!({cond})", "negation")
    return found


def file_mutants(path, text):
    """Every mutant of a file's text, in line order."""
    masked = mask(text).split("\n")
    lines = text.split("\n")
    out = []
    for i, (code, original) in enumerate(zip(masked, lines), start=1):
        if code.strip():
            out.extend(line_mutants(path, i, code, original))
    return out
