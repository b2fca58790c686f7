#include "common/Checked.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "common/Cli.hpp"
#include "common/Csv.hpp"

namespace procsim
{

std::string trimmed(const std::string& text)
{
    const auto b = text.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return "";
    const auto e = text.find_last_not_of(" \t\r\n");
    return text.substr(b, e - b + 1);
}

std::ifstream openInput(const std::string& path, const std::string& what, const std::string& hint)
{
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError(path + ": is a directory, expected " + what);
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot be read (" + hint + ")");
    return in;
}

namespace
{

std::string approx(double v)
{
    return formatNumber(v, 3);
}

constexpr double maxBytes = 8e9; // refuse runs that would need more memory than this

} // namespace

std::optional<double> parseFinite(const std::string& text)
{
    const std::string t = trimmed(text);
    if (t.empty()) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (end != t.c_str() + t.size() || !std::isfinite(v)) return std::nullopt;
    if (errno == ERANGE && std::fabs(v) > 1) return std::nullopt; // overflow (underflow is fine)
    return v;
}

std::optional<long> parseInteger(const std::string& text, long min, long max)
{
    const std::string t = trimmed(text);
    if (t.empty()) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const long v = std::strtol(t.c_str(), &end, 10);
    if (end != t.c_str() + t.size() || errno == ERANGE || v < min || v > max) return std::nullopt;
    return v;
}

long stepCount(double span, double step, long limit, const std::string& where, const std::string& what,
               const std::string& hint)
{
    const double n = std::ceil(span / step - 1e-9);
    if (!(n <= static_cast<double>(limit)))
    {
        throw InputError(where + ": " + what + " needs about " + approx(n) + " steps (limit "
                         + std::to_string(limit) + "); " + hint);
    }
    return std::max(1L, static_cast<long>(n));
}

void checkMemory(double cells, double bytesPerCell, const std::string& where, const std::string& what)
{
    const double bytes = cells * bytesPerCell;
    if (!(bytes <= maxBytes))
    {
        throw InputError(where + ": " + what + " would need about " + approx(bytes / 1e9)
                         + " GB of memory (limit " + approx(maxBytes / 1e9) + " GB)");
    }
}

void checkFileNamePart(const std::string& name, const std::string& where)
{
    bool ok = !name.empty() && name != "." && name != "..";
    for (unsigned char ch : name)
    {
        if (ch == '/' || ch == '\\' || ch < 0x20 || ch == 0x7f) ok = false;
    }
    if (!ok)
    {
        throw InputError(where
                         + " expected a name usable in a file name (no '/', '\\' or control"
                           " characters), got '"
                         + name + "'");
    }
}

void rejectDuplicates(const std::vector<std::string>& names, const std::string& where,
                      const std::string& what)
{
    std::set<std::string> seen;
    for (const auto& n : names)
    {
        if (!seen.insert(n).second) throw InputError(where + ": " + what + " '" + n + "' appears twice");
    }
}

} // namespace procsim
