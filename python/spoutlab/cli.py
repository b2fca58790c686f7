"""The command lines of the case scripts and protocols: argparse parsers
with the module's docstring as their help, and the argument types they
share.  Bad input ends with one line on stderr, status 2: the command, what
was wrong (naming the option) and where the options are listed."""
import argparse


class Parser(argparse.ArgumentParser):
    """argparse, but a bad option is one line, 'PROG: MESSAGE (PROG --help
    lists the options)', not argparse's usage text and error line."""

    def error(self, message):
        self.exit(2, '%s: %s (%s --help lists the options)\n'
                  % (self.prog, ' '.join(message.split()), self.prog))


def parser(prog, doc, epilog=None, **kwargs):
    """A parser whose --help shows doc (a module docstring) as written."""
    return Parser(prog=prog, description=doc, epilog=epilog, allow_abbrev=False,
                  formatter_class=argparse.RawDescriptionHelpFormatter, **kwargs)


def override(text):
    """A key=value override of a case dictionary."""
    key, sep, _ = text.partition('=')
    if not sep or not key or text.startswith('-'):
        raise argparse.ArgumentTypeError('expected key=value, got %r' % text)
    return text


def numbers(text):
    """A comma-separated list of numbers: '1.4,1.6' -> [1.4, 1.6]."""
    try:
        return [float(v) for v in text.split(',')]
    except ValueError:
        raise argparse.ArgumentTypeError('expected numbers separated by commas, got %r' % text)


def pair(text):
    """'U,T': two numbers separated by a comma, kept as written (the case's
    Allrun takes them so)."""
    values = numbers(text)
    if len(values) != 2:
        raise argparse.ArgumentTypeError('expected two numbers U,T, got %r' % text)
    return text


def add_overrides(p, what='system/spoutedBedDict'):
    p.add_argument('overrides', nargs='*', default=[], type=override, metavar='key=value',
                   help='overrides of %s, e.g. He=152 mu=0.063' % what)


def parse(p, argv):
    """Options and key=value overrides in any order: argparse takes the
    first run of overrides, the later ones come back unparsed and are
    appended in order (a later override of a key wins)."""
    a, rest = p.parse_known_args(argv)
    unknown = [x for x in rest if not _is_override(x)]
    if unknown:
        p.error('unrecognized arguments: %s' % ' '.join(unknown))
    if rest:
        a.overrides = list(a.overrides) + rest
    return a


def _is_override(text):
    try:
        return bool(override(text))
    except argparse.ArgumentTypeError:
        return False
