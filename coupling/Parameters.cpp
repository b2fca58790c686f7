#include "Parameters.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace spoutlab
{

namespace
{

// Parse the whole string as a finite double; partial parses ("1.5m") and
// inf/nan are rejected because they are almost always typing errors.
bool parseScalar(const std::string& text, double& value)
{
    if (text.empty()) return false;
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    value = std::strtod(begin, &end);
    if (end == begin || errno == ERANGE) return false;
    while (*end == ' ' || *end == '\t') ++end;
    return *end == '\0' && std::isfinite(value);
}

} // namespace

Parameters::Parameters(std::string context) : context_(std::move(context)) {}

Parameters& Parameters::set(const std::string& key, const std::string& value)
{
    entries_[key] = value;
    return *this;
}

bool Parameters::has(const std::string& key) const
{
    return entries_.count(key) != 0;
}

InputError Parameters::badValue(const std::string& key, const std::string& expected) const
{
    auto found = entries_.find(key);
    const std::string got = found == entries_.end() ? std::string() : found->second;
    return InputError(context_ + ": key '" + key + "' expected " + expected + ", got '" + got + "'");
}

const std::string& Parameters::require(const std::string& key, const std::string& expected) const
{
    auto found = entries_.find(key);
    if (found == entries_.end())
    {
        throw InputError(context_ + ": key '" + key + "' is missing (expected " + expected + ")");
    }
    return found->second;
}

double Parameters::getScalar(const std::string& key) const
{
    double value = 0.0;
    if (!parseScalar(require(key, "a number"), value)) throw badValue(key, "a number");
    return value;
}

double Parameters::getScalar(const std::string& key, double defaultValue) const
{
    return has(key) ? getScalar(key) : defaultValue;
}

long Parameters::getInteger(const std::string& key) const
{
    double value = 0.0;
    const bool ok = parseScalar(require(key, "an integer"), value) && value == std::floor(value)
                    && std::fabs(value) < 1e15;
    if (!ok) throw badValue(key, "an integer");
    return static_cast<long>(value);
}

long Parameters::getInteger(const std::string& key, long defaultValue) const
{
    return has(key) ? getInteger(key) : defaultValue;
}

std::string Parameters::getWord(const std::string& key) const
{
    const std::string& value = require(key, "a word");
    const bool isWord = !value.empty() && value.find_first_of(" \t\n;") == std::string::npos;
    if (!isWord) throw badValue(key, "a word");
    return value;
}

std::string Parameters::getWord(const std::string& key, const std::string& defaultValue) const
{
    return has(key) ? getWord(key) : defaultValue;
}

} // namespace spoutlab
