#pragma once
// The one way a procsim command picks its subcommand ("procsim dryer
// simulate ...", "procsim kinetics run ..."): a table of names, help at every
// level, and one line for an unknown name.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace procsim
{

struct Subcommand
{
    std::string name;
    std::function<int(int, char**)> run; // gets argv from the subcommand's name on
};

// argv[0] is the command (e.g. "dryer"), argv[1] the subcommand.  Without
// one, prints `usage` and returns 2; with -h/--help/help, prints it and
// returns 0; an unknown name throws InputError
// "<command>: unknown command 'x' (see procsim <command> --help)".
// `command` is empty for procsim itself; `noun` names the choices in that
// message ("model" for plume).
int runSubcommand(const std::string& command, std::string_view usage, const std::vector<Subcommand>& table,
                  int argc, char** argv, const std::string& noun = "command");

} // namespace procsim
