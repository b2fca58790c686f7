"""SpoutLab's case layer: what the case scripts (openfoam_cases/*/evaluate,
generate, inletVelocity), the spouted bed's protocols and the tests share.

  foamfile          OpenFOAM dictionaries (#include, $variables), fields and
                    tables: the one reader of OpenFOAM's files
  casefiles         what a run writes besides them: function-object .dat
                    files, coupling.csv, the particle .vtp files; gnuplot
                    pictures and the checks table of the evaluate scripts
  spoutedbed        the slanted-base vessel of spoutDraftPlates (and the
                    settled bed's height and voidage)
  bedmaps           pictures of the vessel: particles, gas cell fields
  spoutingloop      the minimum-spouting protocol's rules and schedule
  spoutcorrelations Kudra's u_ms (eq 12), Ergun's u_mf
  profilefeatures   the features of Figs 4-5 in the time-averaged profiles
  caserun           running the case from a protocol; what a run used
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
  vtkreaders        the runs' ParaView files through VTK's readers (needs
                    VTK's Python, python3-vtk9; etc/paraview/particles.py
                    and tests/view use it)
  protocols         the papers' protocols, one command: python3 -m
                    spoutlab.protocols NAME, which the spouted bed's
                    protocols/NAME run
  bench             the benchmarks of bench/ (figures, no assertions):
                    python3 -m spoutlab.bench NAME, which bench/NAME runs

Finding the package: etc/bashrc puts <repository>/python on PYTHONPATH,
once for everything (the Allrun scripts source it through
etc/caseFunctions, ctest gives the tests the same); scripts import it
plainly, and a case script run without it stops with one line saying what
to source.  python/pyproject.toml makes it installable as well, offline
with Debian's setuptools; the case layer needs etc/bashrc all the same.

Standard library only, except bedlayers, packedbedheat, moistair,
kerneldrying, packedbeddrying and thinlayer's fits (numpy, scipy: Debian's
/usr/bin/python3).
"""
