#pragma once
// Command-line conventions shared by every procsim subcommand.
#include <stdexcept>
#include <string>

namespace procsim
{

// Bad input: the message is ONE line naming the file, the key and what was
// expected, e.g. "case.yaml: key 'reactor.volume' expected a positive number
// [L], got -2".  main() prints it as "procsim: <message>" and exits 1.
class InputError : public std::runtime_error
{
public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// -h, --help or help: the word that asks for a help text
bool isHelp(const std::string& arg);

// Runs a subcommand inside an OutputBatch (its files are put in place only
// if it succeeds), turning InputError and any other exception into one line
// on stderr naming the subcommand, and exit status 1.
int runGuarded(int (*run)(int, char**), int argc, char** argv);

} // namespace procsim
