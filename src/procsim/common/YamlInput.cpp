#include "common/YamlInput.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace procsim
{

std::string relativeTo(const std::string& dir, const std::string& path)
{
    if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
    return (std::filesystem::path(dir) / path).lexically_normal().string();
}

YamlInput YamlInput::load(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
    {
        throw InputError(path + ": cannot be read (missing file?)");
    }
    try
    {
        return YamlInput(YAML::LoadFile(path), path, "");
    }
    catch (const YAML::Exception& e)
    {
        std::ostringstream os;
        os << path << ": line " << e.mark.line + 1 << ": " << e.msg;
        throw InputError(os.str());
    }
}

YamlInput::YamlInput(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path))
{
}

std::string YamlInput::keyPath(const std::string& key) const
{
    return path_.empty() ? key : path_ + "." + key;
}

InputError YamlInput::error(const std::string& key, const std::string& expected) const
{
    std::string got;
    if (node_.IsMap() && node_[key] && node_[key].IsScalar())
    {
        got = ", got '" + node_[key].as<std::string>() + "'";
    }
    else if (node_.IsMap() && !node_[key])
    {
        return InputError(file_ + ": key '" + keyPath(key) + "' is missing (expected "
                          + expected + ")");
    }
    return InputError(file_ + ": key '" + keyPath(key) + "' expected " + expected + got);
}

YAML::Node YamlInput::required(const std::string& key, const std::string& expected) const
{
    if (!node_.IsMap() || !node_[key])
    {
        throw InputError(file_ + ": key '" + keyPath(key) + "' is missing (expected "
                         + expected + ")");
    }
    return node_[key];
}

bool YamlInput::has(const std::string& key) const
{
    return node_.IsMap() && node_[key];
}

YamlInput YamlInput::child(const std::string& key) const
{
    return YamlInput(required(key, "a section"), file_, keyPath(key));
}

std::vector<YamlInput> YamlInput::items() const
{
    if (!node_.IsSequence())
    {
        throw InputError(file_ + ": key '" + path_ + "' expected a list");
    }
    std::vector<YamlInput> out;
    for (std::size_t i = 0; i < node_.size(); ++i)
    {
        out.emplace_back(node_[i], file_, path_ + "[" + std::to_string(i) + "]");
    }
    return out;
}

std::vector<std::string> YamlInput::keys() const
{
    std::vector<std::string> out;
    if (!node_.IsMap()) return out;
    for (const auto& kv : node_) out.push_back(kv.first.as<std::string>());
    return out;
}

double YamlInput::number(const std::string& key, const std::string& unit) const
{
    const std::string expected = "a number" + (unit.empty() ? "" : " [" + unit + "]");
    const YAML::Node n = required(key, expected);
    try
    {
        return n.as<double>();
    }
    catch (const YAML::Exception&)
    {
        throw error(key, expected);
    }
}

double YamlInput::number(const std::string& key, double fallback, const std::string& unit) const
{
    return has(key) ? number(key, unit) : fallback;
}

double YamlInput::positive(const std::string& key, const std::string& unit) const
{
    const double v = number(key, unit);
    if (!(v > 0)) throw error(key, "a positive number" + (unit.empty() ? "" : " [" + unit + "]"));
    return v;
}

double YamlInput::nonNegative(const std::string& key, const std::string& unit) const
{
    const double v = number(key, unit);
    if (!(v >= 0)) throw error(key, "a number >= 0" + (unit.empty() ? "" : " [" + unit + "]"));
    return v;
}

long YamlInput::integer(const std::string& key) const
{
    const YAML::Node n = required(key, "an integer");
    try
    {
        return n.as<long>();
    }
    catch (const YAML::Exception&)
    {
        throw error(key, "an integer");
    }
}

std::string YamlInput::text(const std::string& key) const
{
    const YAML::Node n = required(key, "a word");
    if (!n.IsScalar()) throw error(key, "a word");
    return n.as<std::string>();
}

std::string YamlInput::text(const std::string& key, const std::string& fallback) const
{
    return has(key) ? text(key) : fallback;
}

std::vector<double> YamlInput::numbers(const std::string& key, const std::string& unit) const
{
    const std::string expected = "a list of numbers" + (unit.empty() ? "" : " [" + unit + "]");
    const YAML::Node n = required(key, expected);
    if (!n.IsSequence()) throw error(key, expected);
    std::vector<double> out;
    try
    {
        for (const auto& v : n) out.push_back(v.as<double>());
    }
    catch (const YAML::Exception&)
    {
        throw error(key, expected);
    }
    return out;
}

void YamlInput::rejectUnknown(const std::vector<std::string>& known) const
{
    for (const auto& k : keys())
    {
        if (std::find(known.begin(), known.end(), k) == known.end())
        {
            std::string list;
            for (const auto& kk : known) list += (list.empty() ? "" : ", ") + kk;
            throw InputError(file_ + ": unknown key '" + keyPath(k) + "' (expected one of: "
                             + list + ")");
        }
    }
}

} // namespace procsim
