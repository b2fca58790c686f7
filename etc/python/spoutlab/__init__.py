"""SpoutLab's case layer: what the case scripts (openfoam_cases/*/evaluate,
generate, inletVelocity), the spouted bed's protocols and the tests share.

  foamfile          OpenFOAM dictionaries (#include, $variables), fields and
                    tables: the one reader of OpenFOAM's files
  casefiles         what a run writes besides them: function-object .dat
                    files, coupling.csv, the particle .vtp files; gnuplot
                    pictures and the checks table of the evaluate scripts
  spoutedbed        the slanted-base vessel of spoutDraftPlates and the
                    protocols' rules (u_ms, the schedule, the settled bed)
  spoutregime       the spout classifier
  mixing            the degree of mixing (eqs 17-19, Lacey)
  spoutheat         the heat-transfer post-processing of the spouted bed
  spoutdrying       the drying post-processing of the spouted bed
  heatcorrelations, packedbedheat, draglaws, bedlayers, moistair,
  kerneldrying, packedbeddrying
                    the analytic references of the verification cases
  thinlayer         Thompson's thin-layer equation and the calibration of
                    the kernel diffusivity on it
  decomposition     x-slabs for parallel coupled runs
  cli               the argparse front ends of the scripts and protocols
  protocols         the papers' protocols; openfoam_cases/spoutDraftPlates/
                    protocols/<name> are their commands

Finding the package: every script puts <repository>/etc/python first on
sys.path, the repository being $SPOUTLAB_DIR (etc/bashrc sets it; the case
scripts source etc/caseFunctions, which sources it) or, without it, two
levels above the working directory -- a case directory under
openfoam_cases/:

    sys.path.insert(0, os.path.join(os.environ.get('SPOUTLAB_DIR', '../..'),
                                    'etc', 'python'))
    from spoutlab import spoutedbed

etc/bashrc also puts etc/python on PYTHONPATH, so that the modules with a
command line run as /usr/bin/python3 -m spoutlab.mixing CASE (and
spoutlab.decomposition, spoutlab.spoutregime).

Standard library only, except bedlayers, packedbedheat, moistair,
kerneldrying, packedbeddrying and thinlayer's fits (numpy, scipy: Debian's
/usr/bin/python3).
"""
