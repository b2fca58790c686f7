#pragma once
// The models of `procsim plume`, one file each, each in three steps: parse
// (the command line and the case), run (the model), report (stdout, CSV,
// PNG).  argv[0] is the model's name.

namespace procsim::plume
{

int eulerianCommand(int argc, char** argv);   // EulerianCommand.cpp
int gaussianCommand(int argc, char** argv);   // GaussianCommand.cpp
int monteCarloCommand(int argc, char** argv); // MonteCarloCommand.cpp

} // namespace procsim::plume
