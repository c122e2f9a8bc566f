"""textmate.py: for textmate.sh: a small TextMate tokenizer (match and begin/end rules, their
captures, match rules applied to a capture, includes of the repository and $self) that
prints, for each line of a file, one letter per character for the class of its innermost
scope that has one (the letters of sample.codes); with --words, the words that the grammar's
keyword rules list, one "CLASS WORD" a line. Python's re stands in for Oniguruma: the
grammar keeps to what both read alike. Exit status 1 with a message when the grammar does
not parse or has a rule this tokenizer does not know.

usage: textmate.py GRAMMAR FILE | textmate.py --words GRAMMAR"""
import json
import re
import sys

# scope prefix -> letter; the classes of words by letter
LETTERS = [("keyword.control.statement", "k"), ("entity.other.attribute-name", "a"),
           ("support.function.builtin", "f"), ("entity.name.function", "F"),
           ("constant.language", "c"),
           ("invalid.illegal.povray", "P"), ("invalid.illegal.directive", "D"),
           ("constant.numeric", "n"), ("keyword.operator", "o"), ("string.quoted", "s"),
           ("constant.character.escape", "e"), ("invalid.illegal.escape", "E"),
           ("punctuation.definition.vector", "v"), ("keyword.other.todo", "T"), ("comment", "/")]
CLASSES = {"k": "statement", "a": "attribute", "o": "operator", "f": "function", "c": "constant",
           "P": "povray"}
WORD_LIST = re.compile(r"\\b\(\?:([a-z_0-9|]+)\)\\b")


def letter(scope):
    for prefix, ch in LETTERS:
        if scope == prefix or scope.startswith(prefix + "."):
            return ch
    return None


class Grammar:
    def __init__(self, path):
        with open(path, encoding="utf-8") as f:
            try:
                self.g = json.load(f)
            except json.JSONDecodeError as e:
                sys.exit(f"textmate.py: {path}:{e.lineno}:{e.colno}: {e.msg}")
        self.repo = self.g.get("repository", {})
        self.compiled = {}

    def rules(self, patterns):
        """patterns with their includes resolved, in order"""
        out = []
        for p in patterns:
            if "include" not in p:
                out.append(p)
                continue
            inc = p["include"]
            r = self.g if inc == "$self" else self.repo[inc.lstrip("#")]
            out += [r] if "match" in r or "begin" in r else self.rules(r["patterns"])
        return out

    def rx(self, text):
        if text not in self.compiled:
            self.compiled[text] = re.compile(text)
        return self.compiled[text]

    def tokenize(self, lines):
        """one list of scope lists per line, a scope list per character"""
        stack, out = [], []
        for line in lines:
            scopes = [None] * len(line)

            def paint(a, b, names):
                for i in range(a, min(b, len(line))):
                    scopes[i] = names

            pos = 0
            while True:
                outer = [r["name"] for r in stack if "name" in r]
                cands = [("end", stack[-1], stack[-1]["end"])] if stack else []
                inner = stack[-1].get("patterns", []) if stack else self.g["patterns"]
                cands += [("rule", r, r.get("match", r.get("begin"))) for r in self.rules(inner)]
                best = None
                for kind, r, text in cands:
                    m = self.rx(text).search(line, pos)
                    if m and (best is None or m.start() < best[2].start()):
                        best = (kind, r, m)  # the earliest; on a tie, the end, then the first
                if not best:
                    break
                kind, r, m = best
                if m.end() == m.start() and kind != "end":
                    sys.exit(f"textmate.py: rule {r} matches the empty string")
                paint(pos, m.start(), outer)
                names = outer + ([r["name"]] if kind != "end" and "name" in r else [])
                key = "endCaptures" if kind == "end" else "beginCaptures" if "begin" in r else "captures"
                paint(m.start(), m.end(), names)
                self.captures(line, m, r.get(key, r.get("captures", {})), names, paint)
                if kind == "end":
                    stack.pop()
                elif "begin" in r:
                    stack.append(r)
                pos = m.end()
            paint(pos, len(line), [r["name"] for r in stack if "name" in r])
            out.append(scopes)
        return out

    def captures(self, line, m, caps, names, paint):
        """paints the groups of match m: each its name, and a group's patterns (match rules)
        over its text, as vscode-textmate does: the line up to the group's end, from its start"""
        for group, cap in caps.items():
            a, b = m.start(int(group)), m.end(int(group))
            if a < 0:
                continue
            inner = names + ([cap["name"]] if "name" in cap else [])
            paint(a, b, inner)
            pos, rules = a, self.rules(cap.get("patterns", []))
            while rules:
                found = [(r, self.rx(r["match"]).search(line, pos, b)) for r in rules if "match" in r]
                if len(found) != len(rules):
                    sys.exit("textmate.py: a capture's patterns may only be match rules")
                found = [(r, f) for r, f in found if f]
                if not found:
                    break
                r, f = min(found, key=lambda rf: rf[1].start())  # the earliest; on a tie, the first
                if f.end() == f.start():
                    sys.exit(f"textmate.py: rule {r} matches the empty string")
                names_r = inner + ([r["name"]] if "name" in r else [])
                paint(f.start(), f.end(), names_r)
                self.captures(line, f, r.get("captures", {}), names_r, paint)
                pos = f.end()

    def words(self):
        """(class, word) of each word of the keyword rules"""
        for r in self.rules(self.repo["keywords"]["patterns"]):
            if "name" not in r:
                continue  # a rule that gives classes by its captures
            ch = letter(r["name"])
            m = WORD_LIST.fullmatch(r["match"])
            if ch == "D":
                continue
            if ch not in CLASSES or not m:
                sys.exit(f"textmate.py: keyword rule {r['name']} is not of the form \\b(?:a|b)\\b")
            for w in m.group(1).split("|"):
                yield CLASSES[ch], w


def main(argv):
    if len(argv) == 3 and argv[1] == "--words":
        for cls, w in Grammar(argv[2]).words():
            print(cls, w)
        return 0
    if len(argv) != 3:
        sys.exit(__doc__.split("\n\n")[-1])
    with open(argv[2], encoding="utf-8") as f:
        lines = f.read().split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    for scopes in Grammar(argv[1]).tokenize(lines):
        row = ""
        for names in scopes:
            found = [letter(s) for s in reversed(names or []) if letter(s)]
            row += found[0] if found else "."
        print(row)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
