#pragma once
// Command-line conventions shared by every procsim subcommand.
#include <set>
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

bool isHelp(const std::string& arg);

// Walks a subcommand's arguments (argv[0] is the subcommand): options with
// values and positional words, with one-line errors naming the command and
// the option.
class ArgReader
{
public:
    ArgReader(std::string command, int argc, char** argv);

    bool next();                        // advance; false after the last
    const std::string& arg() const { return arg_; }
    bool isOption() const { return !arg_.empty() && arg_[0] == '-'; }

    std::string value();                // the option's value: the next argument (once per option)
    long positiveInteger();             // value() as a whole number > 0 (within int)
    double finiteNumber();              // value() as a finite number

    // "<command>: unknown option '-x' (see procsim <helpPath> --help)"
    InputError unknown(const std::string& helpPath) const;
    // "<command>: more than one case file given ('b.yaml')"
    InputError extraPositional() const;

private:
    std::string command_;
    int argc_;
    char** argv_;
    int index_ = 0;
    std::string arg_;
    std::set<std::string> given_;
};

// Runs a subcommand inside an OutputBatch (its files are put in place only
// if it succeeds), turning InputError and any other exception into one line
// on stderr naming the subcommand, and exit status 1.
int runGuarded(int (*run)(int, char**), int argc, char** argv);

} // namespace procsim
