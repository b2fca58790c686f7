#include "common/CommandLine.hpp"

#include <iostream>
#include <utility>

#include <CLI/CLI.hpp>

#include "common/Checked.hpp"

namespace procsim
{

CommandLine::CommandLine(std::string command, std::string help)
    : command_(std::move(command)), help_(std::move(help)), app_(std::make_unique<CLI::App>())
{
    app_->set_help_flag(); // procsim's help texts are its own (help/*.txt)
    app_->allow_extras();  // unknown words are reported below, one line each
    app_->add_option("input", inputs_);
}

CommandLine::~CommandLine() = default;

void CommandLine::input(std::string& path, const std::string& what)
{
    input_ = &path;
    inputWhat_ = what;
}

void CommandLine::valued(const std::string& names, std::string& value)
{
    CLI::Option* o = app_->add_option(names, value);
    o->multi_option_policy(CLI::MultiOptionPolicy::TakeLast); // repeats refused after parsing
    once_.push_back(o);
}

void CommandLine::text(const std::string& names, std::string& value)
{
    valued(names, value);
}

void CommandLine::text(const std::string& names, std::optional<std::string>& value)
{
    auto& text = *texts_.emplace_back(std::make_unique<std::string>());
    valued(names, text);
    CLI::Option* o = once_.back();
    convert_.push_back([o, &text, &value] {
        if (o->count() > 0) value = text;
    });
}

void CommandLine::number(const std::string& names, std::optional<double>& value)
{
    auto& text = *texts_.emplace_back(std::make_unique<std::string>());
    valued(names, text);
    CLI::Option* o = once_.back();
    convert_.push_back([this, o, &text, &value] {
        if (o->count() == 0) return;
        value = parseFinite(text);
        if (!value) throw refuse(o->get_name(), "a finite number", text);
    });
}

void CommandLine::integer(const std::string& names, std::optional<long>& value, long min, long max)
{
    auto& text = *texts_.emplace_back(std::make_unique<std::string>());
    valued(names, text);
    CLI::Option* o = once_.back();
    const std::string expected = min == 1 && max == 2147483647L ? "a positive integer"
                                                                : "an integer from " + std::to_string(min)
                                                                      + " to " + std::to_string(max);
    convert_.push_back([this, o, &text, &value, min, max, expected] {
        if (o->count() == 0) return;
        value = parseInteger(text, min, max);
        if (!value) throw refuse(o->get_name(), expected, text);
    });
}

void CommandLine::flag(const std::string& names, bool& value)
{
    once_.push_back(app_->add_flag(names, value));
}

void CommandLine::list(const std::string& names, std::vector<std::string>& values)
{
    // one value per occurrence: "--sweep a=1 --sweep b=2"
    app_->add_option(names, values)->expected(1)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

InputError CommandLine::refuse(const std::string& option, const std::string& expected,
                               const std::string& given) const
{
    return InputError(command_ + ": option " + option + " expected " + expected + ", got '" + given + "'");
}

bool CommandLine::parse(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i)
    {
        if (isHelp(argv[i]))
        {
            std::cout << help_;
            return false;
        }
    }
    try
    {
        app_->parse(argc, argv);
    }
    catch (const CLI::ArgumentMismatch&)
    {
        missingValue(argc, argv);
    }
    catch (const CLI::ParseError& e)
    {
        throw InputError(command_ + ": " + e.what() + " (see procsim " + command_ + " --help)");
    }
    rejectExtras();
    rejectRepeats(argc, argv);
    for (const auto& c : convert_) c();
    if (input_)
    {
        if (inputs_.empty())
            throw InputError(command_ + ": expected one " + inputWhat_ + " (see procsim " + command_
                             + " --help)");
        *input_ = inputs_.front();
    }
    return true;
}

// The first word CLI11 did not take: an unknown option or a second input.
void CommandLine::rejectExtras() const
{
    for (const auto& word : app_->remaining())
    {
        if (!word.empty() && word[0] == '-')
            throw InputError(command_ + ": unknown option '" + word + "' (see procsim " + command_
                             + " --help)");
    }
    const std::size_t allowed = input_ ? 1 : 0;
    if (inputs_.size() > allowed || !app_->remaining().empty())
    {
        const std::string extra = inputs_.size() > allowed ? inputs_[allowed] : app_->remaining().front();
        throw InputError(
            command_ + (input_ ? ": more than one " + inputWhat_ + " given ('" : ": unexpected argument ('")
            + extra + "')");
    }
}

// A second value would silently replace the first.  The message names the
// option as it was typed the second time ("-o", not "--output").
void CommandLine::rejectRepeats(int argc, char** argv) const
{
    for (const CLI::Option* o : once_)
    {
        if (o->count() < 2) continue;
        std::string typed = o->get_name();
        for (int i = 1; i < argc; ++i)
        {
            if (o->check_name(argv[i])) typed = argv[i];
        }
        throw InputError(command_ + ": option " + typed + " given twice");
    }
}

// CLI11 stopped at an option without its value: name it.
void CommandLine::missingValue(int argc, char** argv) const
{
    for (int i = 1; i < argc; ++i)
    {
        const std::string word = argv[i];
        for (const CLI::Option* o : once_)
        {
            if (o->get_type_size() > 0 && o->check_name(word) && (i + 1 >= argc || argv[i + 1][0] == '-'))
                throw InputError(command_ + ": option " + word + " expects a value");
        }
    }
    throw InputError(command_ + ": an option lacks its value (see procsim " + command_ + " --help)");
}

} // namespace procsim
