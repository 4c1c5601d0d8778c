#!/usr/bin/env python3
"""Writes the libFuzzer dictionary of each dialect, tests/fuzz/<dialect>.dict.

    dicts.py          rewrites them
    dicts.py --check  fails if one is not what the grammars and tables give (a test)

A dialect's dictionary holds the literals of its grammar (grammar/<Dialect>*.g4:
keywords, functions, operators, brackets), the codes and addresses of its tables
(stdlib/dialects/<dialect>/), NC-110's three-letter codes, system variables, memories,
formats and functions, and the characters its reader handles before the grammar
(comments, block ends, braces), with a few whole constructs to start from.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
GRAMMARS = {"iso": "Iso", "gost": "Gost", "pp": "Pp", "nc110": "Nc110"}

# What the readers take out before the grammar sees a block (compiler/frontend/<dialect>/),
# and constructs of more than one token.
READER = {
    "iso": ["\n", "\r\n", ";", "(", ")", "{", "}", ",C", ",R", "O1000", "IF [#1 GT 1] THEN ", "IF [#1 EQ 2] GOTO 10",
            "WHILE [#1 LT 3] DO1", "END1", "#1=", "#[#1]", "G65 P1000 A1", "M98 P1000", "M97 P10", "M99"],
    "gost": ["\n", "\r", "\t", "\x00", "\x7f", "%", "(", ")", ":", "/", "N1 "],
    "pp": ["\n", "\r\n", "%", "\"", "*", "N1 ", "R1 ", "G26 R1 R2", "G72 L1", "G73 N", "4.", "5.", "6.", "/1"],
    "nc110": ["\n", "\r\n", ";", "(", ")", ",", "\"", "=", "#", "&", "[", "]", "~", "E30", "E30=", "/MP0", "SA1.1BL",
              "SK7.3CH", "SYVAR 1.4CH", "(DIS,\"", "(RPT,3)", "(ERP)", "(CLS,P1/MP0)", "(EPP,\"A\",\"B\")", "\"A\"",
              "\u0415" "30"],  # a Cyrillic look-alike (lexer CYRILLIC)
}


def grammar_literals(dialect):
    """The quoted literals of the dialect's lexer and parser, as ANTLR reads them."""
    out = []
    for path in sorted((ROOT / "grammar").glob(GRAMMARS[dialect] + "*.g4")):
        text = re.sub(r"//[^\n]*", "", path.read_text())
        for literal in re.findall(r"'((?:[^'\\]|\\.)+)'", text):
            out.append(re.sub(r"\\u([0-9A-Fa-f]{4})|\\(.)",
                              lambda m: chr(int(m[1], 16)) if m[1] else {"n": "\n", "r": "\r", "t": "\t"}.get(m[2], m[2]),
                              literal))
    return out


def table_column(dialect, name, form="{}"):
    """The first column of a table of stdlib/dialects/<dialect>/, each in `form`."""
    path = ROOT / "stdlib" / "dialects" / dialect / name
    if not path.exists():
        return []
    rows = [line.split()[0] for line in path.read_text().splitlines() if line.strip() and not line.startswith("#")]
    return [form.format(row) for row in rows]


def nc110_functions():
    # The functions of NC-110 expressions are a table in the front end, {"SIN", 1, ...}.
    text = (ROOT / "compiler" / "frontend" / "nc110" / "expressions.cpp").read_text()
    return re.findall(r'\{"([A-Z]{3})", [0-9]', text)


def entries(dialect):
    words = grammar_literals(dialect) + READER[dialect]
    for table in ("g_codes.tsv", "m_codes.tsv", "cycles.tsv", "control_codes.tsv", "addresses.tsv"):
        words += table_column(dialect, table)
    if dialect == "iso":
        words += table_column(dialect, "system_variables.tsv", "#{}")
    if dialect == "nc110":
        words += table_column(dialect, "three_letter_codes.tsv", "({},")
        words += table_column(dialect, "three_letter_codes.tsv", "({})")
        for table in ("system_variables.tsv", "memories.tsv", "parameters.tsv"):
            words += table_column(dialect, table)
        words += nc110_functions()
    return sorted(set(words))


def quote(word):
    body = "".join(c if " " <= c <= "~" and c not in "\"\\" else
                   "".join(f"\\x{b:02X}" for b in c.encode()) for c in word)
    return f'"{body}"'


def dictionary(dialect):
    lines = [f"# libFuzzer dictionary of the {dialect} dialect: written by tests/fuzz/dicts.py from",
             f"# grammar/{GRAMMARS[dialect]}*.g4 and stdlib/dialects/{dialect}/ (do not edit)."]
    return "\n".join(lines + [quote(w) for w in entries(dialect)]) + "\n"


def main():
    check = sys.argv[1:] == ["--check"]
    stale = []
    for dialect in GRAMMARS:
        path = ROOT / "tests" / "fuzz" / f"{dialect}.dict"
        text = dictionary(dialect)
        if check:
            if not path.exists() or path.read_text() != text:
                stale.append(path.name)
        else:
            path.write_text(text)
    if stale:
        print(f"{', '.join(stale)}: not what the grammars and tables give; run tests/fuzz/dicts.py")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
