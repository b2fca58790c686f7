#pragma once
// The subcommands of `procsim kinetics`, one file each, each in three steps:
// parse (the command line), run (the model), report (stdout, CSV, PNG).
// argv[0] is the subcommand's name.
#include <string>
#include <vector>

#include "kinetics/Case.hpp"

namespace procsim::kinetics
{

int runCommand(int argc, char** argv);         // RunCommand.cpp
int sensitivityCommand(int argc, char** argv); // SensitivityCommand.cpp
int fitCommand(int argc, char** argv);         // FitCommand.cpp
int coronaCommand(int argc, char** argv);      // CoronaCommand.cpp

// The values of --set KEY=VALUE (run and sensitivity), each key once.
Overrides parseSetOptions(const std::vector<std::string>& words, const std::string& command);

} // namespace procsim::kinetics
