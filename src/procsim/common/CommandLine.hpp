#pragma once
// procsim's one command-line parser, over CLI11: the options and the input
// file of a subcommand, its --help text, and one-line errors that name the
// command and the option:
//   "dryer simulate: option --batch given twice"
//   "kinetics run: unknown option '--bogus' (see procsim kinetics run --help)"
//   "dryer psychro: option --t expected a finite number, got 'inf'"
// Values are read as text and turned into numbers by common/Checked, the
// rules every other input follows.  Every option may be given once, except
// the ones declared as lists.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/Cli.hpp"

namespace CLI
{
class App;
class Option;
} // namespace CLI

namespace procsim
{

class CommandLine
{
public:
    // command: "dryer simulate" (the words after "procsim"); help: its --help text
    CommandLine(std::string command, std::string help);
    ~CommandLine();
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    // The one input file the command reads; what: "plant file".
    void input(std::string& path, const std::string& what);
    // names: "--out" or "-o,--output"; the variable keeps its value when absent
    void text(const std::string& names, std::string& value);
    void text(const std::string& names, std::optional<std::string>& value);
    void number(const std::string& names, std::optional<double>& value);
    void integer(const std::string& names, std::optional<long>& value, long min = 1,
                 long max = 2147483647L); // a whole number within [min, max]
    void flag(const std::string& names, bool& value);
    void list(const std::string& names, std::vector<std::string>& values); // may be repeated

    // Reads argv (argv[0] is the subcommand).  Returns false when --help was
    // asked for: the help text is printed and the command is done.  Bad
    // arguments throw InputError with one line.
    bool parse(int argc, char** argv);

    // "<command>: option <name> expected <expected>, got '<given>'", for the
    // checks a command makes on an option's value.
    InputError refuse(const std::string& option, const std::string& expected, const std::string& given) const;
    const std::string& command() const { return command_; }

private:
    void valued(const std::string& names, std::string& value);
    void rejectExtras() const;
    void rejectRepeats(int argc, char** argv) const;
    void missingValue(int argc, char** argv) const;

    std::string command_;
    std::string help_;
    std::unique_ptr<CLI::App> app_;
    std::vector<CLI::Option*> once_; // options that may appear only once
    std::vector<std::string> inputs_;
    std::string* input_ = nullptr;
    std::string inputWhat_;
    std::vector<std::function<void()>> convert_;
    std::vector<std::unique_ptr<std::string>> texts_; // storage of the typed options' text
};

} // namespace procsim
