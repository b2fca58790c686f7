#pragma once
// The subcommands of `procsim dryer`, one file each, each in three steps:
// parse (the command line), run (the model), report (stdout, CSV, PNG).
// argv[0] is the subcommand's name.

namespace procsim::dryer
{

int metricsCommand(int argc, char** argv);   // MetricsCommand.cpp
int psychroCommand(int argc, char** argv);   // PsychroCommand.cpp
int simulateCommand(int argc, char** argv);  // SimulateCommand.cpp
int calibrateCommand(int argc, char** argv); // CalibrateCommand.cpp
int whatifCommand(int argc, char** argv);    // WhatifCommand.cpp
int spoutedCommand(int argc, char** argv);   // SpoutedCommand.cpp

} // namespace procsim::dryer
