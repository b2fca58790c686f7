#pragma once
// Command-line conventions shared by every procsim subcommand.
#include <stdexcept>
#include <string>

namespace procsim
{

// A message as the one line it is printed on: line breaks (a library's text)
// become spaces, and every other control character (NUL among them), byte
// that is not UTF-8, C1 control or Unicode line or paragraph separator (an
// input file's bytes echoed in the message) is written as \xNN, so no
// terminal or reader sees a second line.
std::string messageLine(const std::string& text);

// Bad input: the message is ONE line naming the file, the key and what was
// expected, e.g. "case.yaml: key 'reactor.volume' expected a positive number
// [L], got -2".  main() prints it as "procsim: <message>" and exits 1.  It is
// kept as messageLine makes it, so an echoed value cannot break or cut it.
class InputError : public std::runtime_error
{
public:
    explicit InputError(const std::string& message) : std::runtime_error(messageLine(message)) {}
};

// -h, --help or help: the word that asks for a help text
bool isHelp(const std::string& arg);

// Runs a subcommand inside an OutputBatch (its files are put in place only
// if it succeeds), turning InputError and any other exception into one line
// on stderr naming the subcommand, and exit status 1.
int runGuarded(int (*run)(int, char**), int argc, char** argv);

} // namespace procsim
