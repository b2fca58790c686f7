"""The benchmarks of bench/ (bench/README.md), as modules: each prints
figures and asserts nothing.  bench/NAME runs one (bench/run, linked under
each name, sources etc/bashrc and runs python3 -m spoutlab.bench NAME);
their shared machinery is imported, not loaded by path (spoutbench: the
settled and the developed spouted bed; couplingoverhead: the environment,
settling and process helpers the column benchmarks share)."""
import os

# the repository whose cases, LIGGGHTS inputs and bench/ inputs they run:
# SPOUTLAB_DIR (etc/bashrc), else the one this package lies in (python/)
REPO = os.environ.get('SPOUTLAB_DIR') or os.path.dirname(os.path.dirname(
    os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
