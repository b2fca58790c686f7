#include "common/YamlInput.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "common/Checked.hpp"
#include "common/Csv.hpp"

namespace procsim
{

namespace
{

std::string joinPath(const std::string& path, const std::string& key)
{
    return path.empty() ? key : path + "." + key;
}

// yaml-cpp keeps the first (or last) of two equal keys without a word; an
// input with a key given twice is refused instead.
void rejectDuplicateKeys(const YAML::Node& node, const std::string& file, const std::string& path)
{
    if (node.IsMap())
    {
        std::set<std::string> seen;
        for (const auto& kv : node)
        {
            const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
            if (!seen.insert(key).second)
            {
                throw InputError(file + ": line " + std::to_string(kv.first.Mark().line + 1) + ": key '"
                                 + joinPath(path, key) + "' is given twice");
            }
            rejectDuplicateKeys(kv.second, file, joinPath(path, key));
        }
    }
    else if (node.IsSequence())
    {
        for (std::size_t i = 0; i < node.size(); ++i)
        {
            rejectDuplicateKeys(node[i], file, path + "[" + std::to_string(i) + "]");
        }
    }
}

std::string withUnit(const std::string& what, const std::string& unit)
{
    return what + (unit.empty() ? "" : " [" + unit + "]");
}

} // namespace

std::string relativeTo(const std::string& dir, const std::string& path)
{
    if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
    return (std::filesystem::path(dir) / path).lexically_normal().string();
}

YamlInput YamlInput::load(const std::string& path)
{
    openInput(path, "an input file");
    try
    {
        YAML::Node root = YAML::LoadFile(path);
        rejectDuplicateKeys(root, path, "");
        return YamlInput(root, path, "");
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
{}

std::string YamlInput::keyPath(const std::string& key) const
{
    return joinPath(path_, key);
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
        return InputError(file_ + ": key '" + keyPath(key) + "' is missing (expected " + expected + ")");
    }
    return InputError(file_ + ": key '" + keyPath(key) + "' expected " + expected + got);
}

YAML::Node YamlInput::required(const std::string& key, const std::string& expected) const
{
    if (!node_.IsMap() || !node_[key])
    {
        throw InputError(file_ + ": key '" + keyPath(key) + "' is missing (expected " + expected + ")");
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
    const std::string expected = withUnit("a finite number", unit);
    const YAML::Node n = required(key, expected);
    const auto v = n.IsScalar() ? parseFinite(n.Scalar()) : std::nullopt;
    if (!v) throw error(key, expected);
    return *v;
}

double YamlInput::number(const std::string& key, double fallback, const std::string& unit) const
{
    return has(key) ? number(key, unit) : fallback;
}

double YamlInput::positive(const std::string& key, const std::string& unit) const
{
    const double v = number(key, unit);
    if (!(v > 0)) throw error(key, withUnit("a positive number", unit));
    return v;
}

double YamlInput::nonNegative(const std::string& key, const std::string& unit) const
{
    const double v = number(key, unit);
    if (!(v >= 0)) throw error(key, withUnit("a number >= 0", unit));
    return v;
}

double YamlInput::within(const std::string& key, double lo, double hi, const std::string& unit) const
{
    const double v = number(key, unit);
    if (!(v >= lo && v <= hi))
    {
        throw error(key, withUnit("a number from " + formatNumber(lo) + " to " + formatNumber(hi), unit));
    }
    return v;
}

double YamlInput::within(const std::string& key, double fallback, double lo, double hi,
                         const std::string& unit) const
{
    return has(key) ? within(key, lo, hi, unit) : fallback;
}

long YamlInput::integer(const std::string& key) const
{
    return integer(key, -2147483647L, 2147483647L);
}

long YamlInput::integer(const std::string& key, long min, long max) const
{
    const std::string expected = "an integer from " + std::to_string(min) + " to " + std::to_string(max);
    const YAML::Node n = required(key, expected);
    const auto v = n.IsScalar() ? parseInteger(n.Scalar(), min, max) : std::nullopt;
    if (!v) throw error(key, expected);
    return *v;
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
    const std::string expected = withUnit("a list of finite numbers", unit);
    const YAML::Node n = required(key, expected);
    if (!n.IsSequence()) throw error(key, expected);
    std::vector<double> out;
    for (std::size_t i = 0; i < n.size(); ++i)
    {
        const auto v = n[i].IsScalar() ? parseFinite(n[i].Scalar()) : std::nullopt;
        if (!v)
        {
            const std::string got = n[i].IsScalar() ? ", got '" + n[i].Scalar() + "'" : "";
            throw InputError(file_ + ": key '" + keyPath(key) + "[" + std::to_string(i) + "]' expected "
                             + withUnit("a finite number", unit) + got);
        }
        out.push_back(*v);
    }
    return out;
}

std::vector<double> YamlInput::increasingNumbers(const std::string& key, const std::string& unit) const
{
    const std::vector<double> v = numbers(key, unit);
    if (v.empty()) throw error(key, withUnit("a non-empty list of numbers", unit));
    for (std::size_t i = 1; i < v.size(); ++i)
    {
        if (!(v[i] > v[i - 1]))
        {
            throw InputError(file_ + ": key '" + keyPath(key) + "[" + std::to_string(i) + "]' expected "
                             + withUnit("values in increasing order", unit) + ", got " + formatNumber(v[i])
                             + " after " + formatNumber(v[i - 1]));
        }
    }
    return v;
}

void YamlInput::rejectUnknown(const std::vector<std::string>& known) const
{
    for (const auto& k : keys())
    {
        if (std::find(known.begin(), known.end(), k) == known.end())
        {
            std::string list;
            for (const auto& kk : known) list += (list.empty() ? "" : ", ") + kk;
            throw InputError(file_ + ": unknown key '" + keyPath(k) + "' (expected one of: " + list + ")");
        }
    }
}

} // namespace procsim
