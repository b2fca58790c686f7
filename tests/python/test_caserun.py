"""The protocols' solver launch (spoutlab.caserun): the last time of a
solver log, and the progress of a run continued after a kill, whose log
already holds times past the write it goes back to (a stand-in solver
writes the times; the rate must come from the times this launch logs)."""
import contextlib
import io
import os
import re
import shutil
import tempfile
import time
import unittest
from unittest import mock

from spoutlab import caserun


class LastTime(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()
        self.log = os.path.join(self.dir, 'log.spoutFoam')

    def tearDown(self):
        shutil.rmtree(self.dir)

    def test_last_time_and_since(self):
        with open(self.log, 'w') as f:
            f.write('Time = 7.6413\nCourant\n')
        size = os.path.getsize(self.log)
        self.assertEqual(caserun.last_time(self.log), 7.6413)
        self.assertIsNone(caserun.last_time(self.log, size))
        with open(self.log, 'a') as f:
            f.write('Starting time loop\nTime = 7.0002\n')
        self.assertEqual(caserun.last_time(self.log, size), 7.0002)
        self.assertIsNone(caserun.last_time(os.path.join(self.dir, 'none')))


class ProgressAfterAKill(unittest.TestCase):
    def test_rate_from_this_launch(self):
        work = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, work)
        os.makedirs(os.path.join(work, 'etc'))
        # the killed run logged up to 7.64 s; the restart goes back to 7.0 s
        # and logs 0.1 s of simulated time per 0.3 s of wall time
        with open(os.path.join(work, 'etc', 'caseFunctions'), 'w') as f:
            f.write('launchSpoutFoam() {\n  for t in 7.0 7.1 7.2 7.3 7.4; do\n'
                    '    echo "Time = $t"; sleep 0.3\n  done\n}\n')
        with open(os.path.join(work, 'log.spoutFoam'), 'w') as f:
            f.write('Time = 7.5\nTime = 7.6413\n')
        real_sleep = time.sleep
        out = io.StringIO()
        cwd = os.getcwd()
        os.chdir(work)
        try:
            with mock.patch.dict(os.environ, {'SPOUTLAB_DIR': work}), \
                    mock.patch('time.sleep', lambda s: real_sleep(0.1)), \
                    contextlib.redirect_stdout(out):
                caserun.run_spoutfoam(8.0, 1, 'test')
        finally:
            os.chdir(cwd)
        rates = [float(r) for r in re.findall(r'([-\d.e+]+) s wall per simulated s', out.getvalue())]
        self.assertTrue(rates, out.getvalue())
        for r in rates:
            self.assertTrue(0.5 < r < 30, out.getvalue())


if __name__ == '__main__':
    unittest.main()
