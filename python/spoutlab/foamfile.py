"""OpenFOAM's ASCII files as the case scripts read them: dictionaries (with
#include and $variables), volume fields, tables and time directories.  The
one reader of the case layer; writing an entry stays foamDictionary -set's.

A dictionary becomes a Dictionary: keys in file order, each value either
the entry's text (between the keyword and its ';', comments removed,
whitespace runs made single spaces, $variables substituted) or a
Dictionary for a sub-dictionary.  Scoped keys are written 'a/b/c', as
foamDictionary -entry takes them.

What is understood, which is what the cases use: // and /* */ comments,
"strings", sub-dictionaries, lists (also of dictionaries, as topoSetDict's
actions), #include and #includeIfPresent (relative to the including file;
$FOAM_CASE and environment variables expanded), $name looked up from the
innermost scope outwards, and a '$name;' entry that merges a dictionary.
An entry given twice takes its later value, and a sub-dictionary given
twice is merged, key by key at every depth (OpenFOAM's default, so a
per-run include at the end of a dictionary overrides its entries).
Other #directives (#includeEtc, #inputMode, #calc) are refused with the
file's name rather than read wrongly.
"""
import os
import re

# a token: a comment, a string, a brace or ';', or a run of anything else
# (words, numbers and parentheses: list text is kept as it stands)
_TOKEN = re.compile(r'\s+|//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\])*"|[{};]|(?:[^\s{};"/]|/(?![/*]))+',
                    re.S)
_VARIABLE = re.compile(r'\$(\{[^}]+\}|[A-Za-z_]\w*)')
REQUIRED = object()


class FoamFileError(SystemExit):
    """Bad input: one line naming the file, the key and what was expected."""


class Dictionary(dict):
    """An OpenFOAM dictionary: insertion-ordered, values str or Dictionary."""

    def __init__(self, path, parent=None):
        super().__init__()
        self.path, self.parent = path, parent

    def lookup(self, name):
        """$name: from this scope outwards (None if nowhere)."""
        scope = self
        while scope is not None:
            if name in scope:
                return scope[name]
            scope = scope.parent
        return None

    def get_entry(self, key, default=REQUIRED):
        """The entry at the scoped key 'a/b/c'."""
        value = self
        for part in key.split('/'):
            if not isinstance(value, Dictionary) or part not in value:
                if default is not REQUIRED:
                    return default
                raise FoamFileError('%s: no entry "%s"' % (self.path, key))
            value = value[part]
        return value


class _Token(str):
    """A token and where it lies in its text (to rebuild an entry's text)."""

    def __new__(cls, m):
        token = super().__new__(cls, m.group())
        token.start, token.end = m.start(), m.end()
        return token


def _tokens(text, path):
    out, covered = [], 0
    for m in _TOKEN.finditer(text):
        covered += len(m.group())
        token = m.group()
        if not (token.isspace() or token.startswith('//') or token.startswith('/*')):
            out.append(_Token(m))
    if covered != len(text):
        raise FoamFileError('%s: unreadable text (an unterminated string or comment?)' % path)
    return out


def _joined(tokens):
    """Tokens as text: adjacent ones together, others one space apart."""
    text = tokens[0] if tokens else ''
    for a, b in zip(tokens, tokens[1:]):
        text += ('' if a.end == b.start else ' ') + b
    return text


def _case_of(path):
    """The case directory of a file in <case>/{system,constant,0.orig,<time>}."""
    return os.path.dirname(os.path.dirname(os.path.abspath(path)))


def _expand(text, scope, path):
    def value(m):
        name = m.group(1).strip('{}')
        if name == 'FOAM_CASE':
            return _case_of(path)
        found = scope.lookup(name) if scope is not None else None
        if isinstance(found, str):
            return found
        if name in os.environ:
            return os.environ[name]
        return m.group()           # left as written (e.g. a macro of the solver's)
    return _VARIABLE.sub(value, text)


def _include(dictionary, token, path):
    target = _expand(token.strip('"'), dictionary, path)
    if not os.path.isabs(target):
        target = os.path.join(os.path.dirname(path), target)
    return target


def _parse(tokens, k, dictionary, path):
    """Entries into dictionary from tokens[k] up to a closing '}' or the
    end; returns the index after it."""
    while k < len(tokens):
        key = tokens[k]
        if key == '}':
            if dictionary.parent is None:
                raise FoamFileError('%s: a "}" without its "{"' % path)
            return k + 1
        if key == ';':
            k += 1
            continue
        if key in ('#include', '#includeIfPresent'):
            if k + 1 >= len(tokens):
                raise FoamFileError('%s: %s: expected a file name' % (path, key))
            target = _include(dictionary, tokens[k + 1], path)
            if os.path.isfile(target):
                with open(target) as f:
                    text = f.read()
                _parse(_tokens(text, target), 0, dictionary, target)
            elif key == '#include':
                raise FoamFileError('%s: #include %s: no such file' % (path, tokens[k + 1]))
            k += 2
            continue
        if key.startswith('#'):
            raise FoamFileError('%s: %s: directive not understood by the case scripts'
                                % (path, key))
        key = key.strip('"')
        if k + 1 < len(tokens) and tokens[k + 1] == '{':
            sub = Dictionary(path, dictionary)
            if isinstance(dictionary.get(key), Dictionary):
                sub.update(dictionary[key])   # given again: merged, as OpenFOAM does
            k = _parse(tokens, k + 2, sub, path)
            dictionary[key] = sub
            continue
        if key.startswith('$') and k + 1 < len(tokens) and tokens[k + 1] in (';', '}'):
            merged = dictionary.lookup(key[1:])
            if isinstance(merged, Dictionary):
                dictionary.update(merged)
            k += 2 if tokens[k + 1] == ';' else 1
            continue
        # the value: up to ';' outside parentheses (lists may hold {...;})
        depth, value, k = 0, [], k + 1
        while k < len(tokens) and not (depth == 0 and tokens[k] in (';', '}')):
            depth += tokens[k].count('(') - tokens[k].count(')')
            value.append(tokens[k])
            k += 1
        if k >= len(tokens) or tokens[k] != ';':
            raise FoamFileError('%s: entry "%s": expected a value ending in ";"' % (path, key))
        dictionary[key] = _expand(_joined(value), dictionary, path)
        k += 1
    return k


def read(path):
    """The Dictionary of an OpenFOAM dictionary file."""
    try:
        with open(path) as f:
            text = f.read()
    except OSError as e:
        raise FoamFileError('%s: cannot read (%s)' % (path, e.strerror))
    dictionary = Dictionary(path)
    tokens = _tokens(text, path)
    _parse(tokens, 0, dictionary, path)
    return dictionary


def entry(path, key, default=REQUIRED):
    """The text (or Dictionary) of one entry, 'a/b/c' for a scoped key."""
    return read(path).get_entry(key, default)


def parse_value(text, path='', key=''):
    """An entry's text as numbers, words and nested lists:
    '(0 (1 2 3))' -> [0.0, [1.0, 2.0, 3.0]]; a bare word or number alone."""
    items = re.findall(r'\(|\)|[^\s()]+', text)
    stack = [[]]
    for item in items:
        if item == '(':
            stack.append([])
        elif item == ')':
            if len(stack) == 1:
                raise FoamFileError('%s: entry "%s": unbalanced ")" in %r' % (path, key, text))
            done = stack.pop()
            stack[-1].append(done)
        else:
            try:
                stack[-1].append(float(item))
            except ValueError:
                stack[-1].append(item)
    if len(stack) != 1:
        raise FoamFileError('%s: entry "%s": unbalanced "(" in %r' % (path, key, text))
    return stack[0][0] if len(stack[0]) == 1 else stack[0]


def scalar(path, key):
    """A number entry ('uniform' allowed before it)."""
    value = parse_value(re.sub(r'^uniform\s+', '', _text(path, key)), path, key)
    if not isinstance(value, float):
        raise FoamFileError('%s: entry "%s": expected a number, got %r'
                            % (path, key, _text(path, key)))
    return value


def vector(path, key):
    """A vector entry '(x y z)' ('uniform' allowed before it) as a tuple."""
    value = parse_value(re.sub(r'^uniform\s+', '', _text(path, key)), path, key)
    if not (isinstance(value, list) and len(value) == 3
            and all(isinstance(v, float) for v in value)):
        raise FoamFileError('%s: entry "%s": expected a vector (x y z), got %r'
                            % (path, key, _text(path, key)))
    return tuple(value)


def _text(path, key):
    value = entry(path, key)
    if isinstance(value, Dictionary):
        raise FoamFileError('%s: entry "%s": expected a value, got a dictionary' % (path, key))
    return value


def table(text, path='', key=''):
    """An OpenFOAM table, '( (t value) ... )' with a number or a vector as
    the value (also after the word 'table'): [(t, value)]."""
    value = parse_value(re.sub(r'^table\s+', '', text.strip()), path, key)
    rows = []
    for row in value if isinstance(value, list) else [None]:
        if not (isinstance(row, list) and len(row) == 2 and isinstance(row[0], float)):
            raise FoamFileError('%s: %s: expected a table of (time value) rows, got %r'
                                % (path, key or 'table', row))
        rows.append((row[0], tuple(row[1]) if isinstance(row[1], list) else row[1]))
    return rows


def read_table(path):
    """A file that holds one table and comments (as constant/inletVelocity)."""
    with open(path) as f:
        return table(_joined(_tokens(f.read(), path)), path)


def read_field(path):
    """internalField of an ASCII OpenFOAM volume field: a list of floats or
    of (x, y, z) tuples ('uniform' values are returned as one-element lists).
    Regular expressions, not the dictionary parser: fields are long."""
    with open(path) as f:
        text = f.read()
    m = re.search(r'internalField\s+uniform\s+([^;]+);', text)
    if m:
        value = m.group(1).strip()
        if value.startswith('('):
            return [tuple(float(v) for v in value.strip('()').split())]
        return [float(value)]
    m = re.search(r'internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\((.*?)\)\s*;',
                  text, re.S)
    if not m:
        raise FoamFileError('%s: internalField: expected uniform VALUE or nonuniform '
                            'List<scalar|vector> N (...)' % path)
    kind, n, body = m.group(1), int(m.group(2)), m.group(3)
    if kind == 'scalar':
        values = [float(v) for v in body.split()]
    else:
        numbers = [float(v) for v in body.replace('(', ' ').replace(')', ' ').split()]
        values = [tuple(numbers[i:i + 3]) for i in range(0, len(numbers), 3)]
    if len(values) != n:
        raise ValueError('%s: expected %d values, read %d' % (path, n, len(values)))
    return values


def time_dirs(case='.'):
    """[(time, name as written)] of a case's time directories, oldest first."""
    times = []
    for name in os.listdir(case):
        try:
            if os.path.isdir(os.path.join(case, name)):
                times.append((float(name), name))
        except ValueError:
            pass      # not a time (0.orig, constant, system, ...)
    return sorted(times)


def latest_time(case='.'):
    """The newest time directory of a case (as its name)."""
    return time_dirs(case)[-1][1]
