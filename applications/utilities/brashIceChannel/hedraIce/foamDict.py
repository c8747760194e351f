"""A reader of OpenFOAM dictionaries (the subset the Hedra tools need).

Supports: keyword value; entries, sub-dictionaries { }, lists ( ) of numbers,
words, strings and lists, // and /* */ comments, a FoamFile header.  Every
lookup goes through Dict.get / Dict.sub, which stop with an OpenFOAM-style
"FOAM FATAL IO ERROR" naming the file and the entry (and the line) on a
missing, ill-typed or out-of-range entry; Dict.check_keys refuses unknown
entries with the closest valid name, as Hedra's C++ readers do.
"""
import difflib
import re
import sys


class FatalIOError(Exception):
    """Raised with the OpenFOAM-style message; tools print it and exit 1."""


def fatal(msg, file, entry=None, line=None):
    where = f"\n    file: {file}" + (f" at line {line}" if line else "")
    ent = f"\n    entry: {entry}" if entry else ""
    raise FatalIOError(f"\n--> FOAM FATAL IO ERROR:\n    {msg}{where}{ent}\n")


_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[{}();]|[^\s{}();"]+')


def _strip_comments(text):
    out, i, n = [], 0, len(text)
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            seg = text[i:(n if j < 0 else j + 2)]
            out.append("\n" * seg.count("\n"))  # keep line numbers
            i = n if j < 0 else j + 2
        else:
            out.append(text[i])
            i += 1
    return "".join(out)


def _tokens(text):
    text = _strip_comments(text)
    line = 1
    pos = 0
    for m in _TOKEN.finditer(text):
        line += text.count("\n", pos, m.start())
        pos = m.start()
        yield m.group(0), line


def _number(tok):
    try:
        return int(tok)
    except ValueError:
        pass
    try:
        return float(tok)
    except ValueError:
        return None


class Dict:
    """A dictionary with its path (for messages) and the lines of its entries."""

    def __init__(self, file, path=""):
        self.file = file
        self.path = path
        self.entries = {}
        self.lines = {}
        self.line = None

    # -- parsing ---------------------------------------------------------
    @classmethod
    def read(cls, file):
        try:
            with open(file) as f:
                text = f.read()
        except OSError as e:
            fatal(f"cannot open the dictionary: {e.strerror}", file)
        toks = list(_tokens(text))
        d = cls(file)
        i = d._parse(toks, 0, top=True)
        d.entries.pop("FoamFile", None)
        return d

    def _parse(self, toks, i, top=False):
        while i < len(toks):
            tok, line = toks[i]
            if tok == "}":
                if top:
                    fatal("unmatched '}'", self.file, line=line)
                return i + 1
            if tok in "{}();" or tok.startswith('"'):
                fatal(f"expected a keyword, found '{tok}'", self.file,
                      self.path or None, line)
            key = tok
            i += 1
            if i >= len(toks):
                fatal(f"entry '{key}' without a value", self.file, self._p(key), line)
            if toks[i][0] == "{":
                sub = Dict(self.file, self._p(key))
                sub.line = line
                i = sub._parse(toks, i + 1)
                self._set(key, sub, line)
                continue
            values = []
            while i < len(toks) and toks[i][0] != ";":
                if toks[i][0] in "{}":
                    fatal(f"missing ';' after entry '{key}'", self.file,
                          self._p(key), toks[i][1])
                v, i = self._value(toks, i, key)
                values.append(v)
            if i >= len(toks):
                fatal(f"missing ';' after entry '{key}'", self.file, self._p(key), line)
            i += 1
            self._set(key, values[0] if len(values) == 1 else values, line)
        if not top:
            fatal("missing '}'", self.file, self.path)
        return i

    def _value(self, toks, i, key):
        tok, line = toks[i]
        if tok == "(":
            lst = []
            i += 1
            while i < len(toks) and toks[i][0] != ")":
                if toks[i][0] == "{":
                    sub = Dict(self.file, f"{self._p(key)}[{len(lst)}]")
                    sub.line = toks[i][1]
                    i = sub._parse(toks, i + 1)
                    lst.append(sub)
                    continue
                if toks[i][0] in "};":
                    fatal(f"unterminated list in entry '{key}'", self.file,
                          self._p(key), toks[i][1])
                v, i = self._value(toks, i, key)
                lst.append(v)
            if i >= len(toks):
                fatal(f"unterminated list in entry '{key}'", self.file, self._p(key), line)
            return lst, i + 1
        if tok.startswith('"'):
            return tok[1:-1], i + 1
        num = _number(tok)
        return (tok if num is None else num), i + 1

    def _set(self, key, value, line):
        if key in self.entries:
            fatal(f"entry '{key}' given twice", self.file, self._p(key), line)
        self.entries[key] = value
        self.lines[key] = line

    def _p(self, key):
        return f"{self.path}/{key}" if self.path else key

    # -- lookup ------------------------------------------------------------
    def __contains__(self, key):
        return key in self.entries

    def keys(self):
        return list(self.entries)

    def error(self, key, msg):
        fatal(msg, self.file, self._p(key), self.lines.get(key, self.line))

    def sub(self, key):
        if key not in self.entries:
            self.error(key, f"missing sub-dictionary '{key}'")
        v = self.entries[key]
        if not isinstance(v, Dict):
            self.error(key, f"'{key}' must be a dictionary {{ ... }}")
        return v

    def get(self, key, kind=float, default=None, min=None, max=None,
            strict_min=False, choices=None, length=None):
        """kind: float, int, str, 'vector' (3 floats), 'list' (a list) or bool."""
        if key not in self.entries:
            if default is not None:
                return default
            for k, v in self.entries.items():  # swallowed by an entry without ';'?
                if isinstance(v, list) and key in v:
                    self.error(k, f"missing entry '{key}': is a ';' missing after "
                               f"entry '{k}' (its value reads '{_show(v)}')?")
            self.error(key, f"missing entry '{key}'")
        v = self.entries[key]
        if kind in (float, int):
            if isinstance(v, bool) or not isinstance(v, (int, float)):
                self.error(key, f"'{key}' must be a number, not '{_show(v)}'")
            if kind is int and not isinstance(v, int):
                self.error(key, f"'{key}' must be an integer, not '{v}'")
            v = kind(v)
            if min is not None and (v < min or (strict_min and v == min)):
                self.error(key, f"'{key}' = {v} must be {'>' if strict_min else '>='} {min}")
            if max is not None and v > max:
                self.error(key, f"'{key}' = {v} must be <= {max}")
            return v
        if kind is bool:
            words = {"true": True, "yes": True, "on": True, "false": False,
                     "no": False, "off": False}
            if not isinstance(v, str) or v not in words:
                self.error(key, f"'{key}' must be true or false, not '{_show(v)}'")
            return words[v]
        if kind is str:
            if not isinstance(v, str):
                self.error(key, f"'{key}' must be a word, not '{_show(v)}'")
            if choices is not None and v not in choices:
                close = difflib.get_close_matches(v, choices, 1)
                hint = f" (did you mean '{close[0]}'?)" if close else ""
                self.error(key, f"unknown {key} '{v}'{hint}; valid: {' '.join(choices)}")
            return v
        if kind == "vector":
            if (not isinstance(v, list) or len(v) != 3
                    or not all(isinstance(x, (int, float)) for x in v)):
                self.error(key, f"'{key}' must be a vector (x y z), not '{_show(v)}'")
            return [float(x) for x in v]
        if kind == "list":
            if not isinstance(v, list):
                self.error(key, f"'{key}' must be a list ( ... ), not '{_show(v)}'")
            if length is not None and len(v) < length:
                self.error(key, f"'{key}' needs at least {length} items")
            return v
        raise ValueError(kind)

    def check_keys(self, valid):
        for k in self.entries:
            if k not in valid:
                close = difflib.get_close_matches(k, valid, 1)
                hint = f" (did you mean '{close[0]}'?)" if close else ""
                self.error(k, f"unknown entry '{k}'{hint}; valid: {' '.join(valid)}")


def _show(v):
    if isinstance(v, list):
        return "(" + " ".join(_show(x) for x in v) + ")"
    if isinstance(v, Dict):
        return "{...}"
    return str(v)


def run_main(main):
    """Run a tool's main(): a FatalIOError is printed and exits 1."""
    try:
        sys.exit(main())
    except FatalIOError as e:
        sys.stderr.write(str(e))
        sys.exit(1)


def header(cls, obj, location=None):
    loc = f'    location    "{location}";\n' if location else ""
    return ("/*--------------------------------*- C++ -*----------------------------------*\\\n"
            "  Hedra (OpenFOAM v1912)\n"
            "\\*---------------------------------------------------------------------------*/\n"
            "FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
            f"    class       {cls};\n{loc}    object      {obj};\n}}\n")
