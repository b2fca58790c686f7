"""The case layer's one reader of OpenFOAM files (spoutlab.foamfile): small
dictionaries and fields written here with their values known, and the
repository's own case dictionaries read against foamDictionary (OpenFOAM's
reader) where it is installed."""
import os
import shutil
import subprocess
import tempfile
import unittest

from spoutlab import foamfile

REPOSITORY = os.path.abspath(os.environ.get('SPOUTLAB_DIR', '../..'))

HEADER = 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class dictionary;\n}\n'


class Files(unittest.TestCase):
    def setUp(self):
        self.case = tempfile.mkdtemp()
        for d in ('system', 'constant', '0'):
            os.makedirs(os.path.join(self.case, d))

    def tearDown(self):
        shutil.rmtree(self.case)

    def write(self, name, text):
        path = os.path.join(self.case, name)
        with open(path, 'w') as f:
            f.write(text)
        return path


class Dictionaries(Files):
    def test_entries_sub_dictionaries_and_comments(self):
        path = self.write('system/controlDict', HEADER + '''
/* a block comment with a ; and a { inside */
endTime 2;          // a line comment; not an entry
deltaT  3e-4;
libs    (sampling "lib two");
functions
{
    probe
    {
        probeLocations  ((0 0.02 0.011));
        fields          (p);
    }
}
''')
        d = foamfile.read(path)
        self.assertEqual(list(d), ['FoamFile', 'endTime', 'deltaT', 'libs', 'functions'])
        self.assertEqual(d['endTime'], '2')
        self.assertEqual(foamfile.scalar(path, 'deltaT'), 3e-4)
        self.assertEqual(d['libs'], '(sampling "lib two")')
        self.assertEqual(foamfile.entry(path, 'functions/probe/fields'), '(p)')
        self.assertEqual(foamfile.parse_value(
            foamfile.entry(path, 'functions/probe/probeLocations')), [[0.0, 0.02, 0.011]])
        self.assertEqual(foamfile.entry(path, 'FoamFile/class'), 'dictionary')

    def test_lists_of_dictionaries_and_keywords_with_parentheses(self):
        path = self.write('system/fvSchemes', '''
divSchemes { default none; div(phi,T) Gauss limitedLinear 1; "div(phi,(U|k))" Gauss upwind; }
actions
(
    { name solid; type cellSet; action new; }
    { name gas; type cellSet; action invert; }
);
after 1;
''')
        self.assertEqual(foamfile.entry(path, 'divSchemes/div(phi,T)'), 'Gauss limitedLinear 1')
        self.assertEqual(foamfile.entry(path, 'divSchemes/div(phi,(U|k))'), 'Gauss upwind')
        # the ';' inside the list's dictionaries do not end the entry
        self.assertTrue(foamfile.entry(path, 'actions').startswith('( { name solid;'))
        self.assertEqual(foamfile.entry(path, 'after'), '1')

    def test_includes_and_variables(self):
        self.write('constant/heatTransfer', 'Tin 423.15;\nT0 306.15;\n')
        self.write('system/probes', 'axis ((0 0.02 0.5035));\n')
        path = self.write('0/T', HEADER + '''
#include "$FOAM_CASE/constant/heatTransfer"
internalField   uniform $T0;
boundaryField
{
    inlet { type fixedValue; value uniform $Tin; }
    probes { #include "../system/probes" where $axis; }
}
''')
        self.assertEqual(foamfile.scalar(path, 'internalField'), 306.15)
        self.assertEqual(foamfile.scalar(path, 'boundaryField/inlet/value'), 423.15)
        # an included entry of a sub-dictionary is seen from inside it
        self.assertEqual(foamfile.entry(path, 'boundaryField/probes/where'), '((0 0.02 0.5035))')

    def test_a_dollar_entry_merges_a_dictionary(self):
        path = self.write('system/fvSolution', '''
solvers
{
    p { solver PCG; tolerance 1e-7; }
    pFinal { $p; relTol 0; }
}
''')
        self.assertEqual(dict(foamfile.entry(path, 'solvers/pFinal')),
                         {'solver': 'PCG', 'tolerance': '1e-7', 'relTol': '0'})

    def test_a_later_entry_overrides_and_dictionaries_merge(self):
        self.write('system/controlDict.options',
                   'endTime 0.5;\nfunctions { averages { timeStart 0.3; } }\n')
        path = self.write('system/controlDict', MERGED)
        self.assertEqual(foamfile.scalar(path, 'endTime'), 0.5)
        self.assertEqual(foamfile.scalar(path, 'writeInterval'), 0.1)
        self.assertEqual(dict(foamfile.entry(path, 'functions/averages')),
                         {'type': 'fieldAverage', 'timeStart': '0.3'})
        self.assertEqual(foamfile.entry(path, 'functions/probe/fields'), '(p)')

    def test_bad_input_names_the_file_and_the_key(self):
        path = self.write('constant/transportProperties', 'rho 1.2;\nmu (1 2 3);\ng { x 1; }\n')
        for key, expected in (('nu', 'no entry "nu"'),
                              ('mu', 'entry "mu": expected a number'),
                              ('g', 'entry "g": expected a value, got a dictionary')):
            with self.assertRaises(foamfile.FoamFileError) as e:
                foamfile.scalar(path, key)
            self.assertTrue(str(e.exception).startswith(path + ': '))
            self.assertIn(expected, str(e.exception))
            self.assertEqual(len(str(e.exception).splitlines()), 1)
        self.assertEqual(foamfile.entry(path, 'nu', 'absent'), 'absent')
        self.assertEqual(foamfile.vector(path, 'mu'), (1.0, 2.0, 3.0))
        for text, expected in (('a 1\n', 'entry "a": expected a value ending in ";"'),
                               ('#includeEtc "caseDicts/x"\n', '#includeEtc: directive not'),
                               ('a "open;\n', 'unreadable text'),
                               ('a 1; }\n', 'a "}" without its "{"')):
            bad = self.write('constant/bad', text)
            with self.assertRaises(foamfile.FoamFileError) as e:
                foamfile.read(bad)
            self.assertIn(bad, str(e.exception))
            self.assertIn(expected, str(e.exception))


class Values(Files):
    def test_tables(self):
        self.assertEqual(foamfile.table('table ((0 (0 0 0.3)) (0.55 (0 0 0.3)) (0.6 1.5))'),
                         [(0.0, (0.0, 0.0, 0.3)), (0.55, (0.0, 0.0, 0.3)), (0.6, 1.5)])
        path = self.write('constant/inletVelocity',
                          '// slot velocity; a comment (with parentheses)\n(\n'
                          '    (0 (0 0 30))\n    (0.1 (0 0 22.5))\n)\n')
        self.assertEqual(foamfile.read_table(path), [(0.0, (0.0, 0.0, 30.0)),
                                                     (0.1, (0.0, 0.0, 22.5))])
        with self.assertRaises(foamfile.FoamFileError):
            foamfile.table('((0 1 2))', 'somewhere', 'uniformValue')

    def test_fields(self):
        scalars = self.write('0/p', HEADER + 'dimensions [0 2 -2 0 0];\n'
                             'internalField nonuniform List<scalar> 3 (1.5 -2 3e-3);\n'
                             'boundaryField { }\n')
        vectors = self.write('0/U', HEADER + 'internalField nonuniform List<vector>\n2\n'
                             '(\n(1 2 3)\n(-4 5e-1 6)\n)\n;\nboundaryField { }\n')
        uniform = self.write('0/T', 'internalField uniform 293.15;\n')
        uniform_vector = self.write('0/V', 'internalField uniform (0 0 2);\n')
        self.assertEqual(foamfile.read_field(scalars), [1.5, -2.0, 0.003])
        self.assertEqual(foamfile.read_field(vectors), [(1.0, 2.0, 3.0), (-4.0, 0.5, 6.0)])
        self.assertEqual(foamfile.read_field(uniform), [293.15])
        self.assertEqual(foamfile.read_field(uniform_vector), [(0.0, 0.0, 2.0)])
        short = self.write('0/q', 'internalField nonuniform List<scalar> 3 (1 2);\n')
        with self.assertRaises(ValueError):
            foamfile.read_field(short)

    def test_latest_time(self):
        for name in ('0.orig', '0.1', '0.25', '10'):
            os.makedirs(os.path.join(self.case, name))
        self.assertEqual(foamfile.latest_time(self.case), '10')


# entries of the repository's cases, read by foamDictionary and by foamfile;
# the values compared as numbers (foamDictionary writes its own format)
AGAINST_FOAM = [
    ('spoutDraftPlates/system/controlDict', 'deltaT'),
    ('spoutDraftPlates/system/controlDict', 'functions/spoutFlux/probeLocations'),
    ('spoutDraftPlates/system/controlDict', 'functions/averages/timeStart'),
    ('spoutDraftPlates/system/controlDict', 'functions/pressureProbe/probeLocations'),
    ('spoutDraftPlates/system/spoutedBedDict', 'dtDem'),
    ('spoutDraftPlates/system/spoutedBedDict', 'muGasHot'),
    ('lumpedHeating/constant/transportProperties', 'rho'),
    ('lumpedHeating/constant/transportProperties', 'kappa'),
    ('lumpedHeating/constant/couplingProperties', 'liggghtsVariables/cpp'),
    ('lumpedHeating/constant/couplingProperties', 'voidFractionModel'),
    ('lumpedHeating/0.orig/U', 'boundaryField/inlet/value'),
    ('packedBedHeating/system/fvSchemes', 'divSchemes/div(phi,T)'),
    ('packedBedHeating/0.orig/T', 'internalField'),
    ('packedBed/0.orig/U', 'boundaryField/inlet/uniformValue'),
    ('settlingParticle/constant/g', 'value'),
    ('settlingParticle/constant/couplingProperties', 'lostParticles'),
]


# a dictionary with a per-run include at its end (as the cases' Allrun write)
MERGED = HEADER + '''
endTime 2;
writeInterval 0.1;
functions
{
    averages { type fieldAverage; timeStart 0.2; }
    probe { fields (p); }
}
#includeIfPresent "controlDict.options"
'''


FOAM_ENV = dict(os.environ, WM_PROJECT='OpenFOAM', WM_PROJECT_VERSION='v1912',
                WM_PROJECT_DIR='/usr/share/openfoam', FOAM_ETC='/usr/share/openfoam/etc',
                FOAM_API='1912')


@unittest.skipUnless(shutil.which('foamDictionary'), 'foamDictionary not installed')
class AgainstFoamDictionary(unittest.TestCase):
    def test_the_cases_dictionaries(self):
        env = FOAM_ENV
        cases = os.path.join(REPOSITORY, 'openfoam_cases')
        for name, key in AGAINST_FOAM:
            path = os.path.join(cases, name)
            with self.subTest(file=name, key=key):
                # OpenFOAM warns on stdout when PWD is not the working directory
                theirs = subprocess.run(['foamDictionary', '-entry', key, '-value', path],
                                        capture_output=True, text=True, cwd=cases,
                                        env=dict(env, PWD=cases))
                self.assertEqual(theirs.returncode, 0, theirs.stderr)
                ours = foamfile.entry(path, key)
                self.assertEqual(foamfile.parse_value(ours),
                                 foamfile.parse_value(theirs.stdout.strip()))

    def test_a_per_run_include_overrides_as_in_openfoam(self):
        case = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, case)
        os.makedirs(os.path.join(case, 'system'))
        with open(os.path.join(case, 'system', 'controlDict.options'), 'w') as f:
            f.write('endTime 0.5;\nfunctions { averages { timeStart 0.3; } }\n')
        path = os.path.join(case, 'system', 'controlDict')
        with open(path, 'w') as f:
            f.write(MERGED)
        for key in ('endTime', 'writeInterval', 'functions/averages/type',
                    'functions/averages/timeStart', 'functions/probe/fields'):
            with self.subTest(key=key):
                theirs = subprocess.run(['foamDictionary', '-entry', key.replace('/', '.'),
                                         '-value', path], capture_output=True, text=True,
                                        cwd=case, env=dict(FOAM_ENV, PWD=case))
                self.assertEqual(theirs.returncode, 0, theirs.stderr)
                self.assertEqual(foamfile.parse_value(foamfile.entry(path, key)),
                                 foamfile.parse_value(theirs.stdout.strip()))


if __name__ == '__main__':
    unittest.main()
