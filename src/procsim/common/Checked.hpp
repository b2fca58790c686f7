#pragma once
// The one place where procsim turns text into numbers, counts steps and
// checks names that become file names, so every input goes through the same
// rules: a number is finite and fills the whole text, a step count fits in
// memory and time, a name is usable as part of a file name.
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace procsim
{

// `text` without the blanks (space, tab, CR, LF) around it.
std::string trimmed(const std::string& text);

// The input file `path` open for reading, or an InputError naming it:
// "<path>: is a directory, expected <what>" or "<path>: cannot be read (<hint>)".
std::ifstream openInput(const std::string& path, const std::string& what,
                        const std::string& hint = "missing file?");

// The whole of `text` (surrounding blanks allowed) as a finite number, or
// nothing: "12.5abc", "", "inf", ".nan" and overflowing values like 1e400
// are all refused.  YAML's ".inf"/".nan" spellings are refused too.
std::optional<double> parseFinite(const std::string& text);

// The whole of `text` as an integer within [min, max], or nothing.
std::optional<long> parseInteger(const std::string& text, long min, long max);

// Steps of length `step` covering `span` (at least 1), computed in double so
// a tiny step cannot overflow.  A count above `limit` is refused with an
// InputError "<where>: <what> needs about N steps (limit L); <hint>".
long stepCount(double span, double step, long limit, const std::string& where, const std::string& what,
               const std::string& hint);

// Refuses (InputError) a size whose memory estimate `cells * bytesPerCell`
// exceeds the cap, giving the estimate.
void checkMemory(double cells, double bytesPerCell, const std::string& where, const std::string& what);

// A name that becomes part of an output file name: non-empty, no '/', '\\',
// control characters, and not "." or "..".  `where` starts the message.
void checkFileNamePart(const std::string& name, const std::string& where);

// The first name that appears twice -> InputError "<where>: <what> 'x' appears twice".
void rejectDuplicates(const std::vector<std::string>& names, const std::string& where,
                      const std::string& what);

// The same for the member `name` of each item, e.g. (receptors, &Receptor::name, ...).
template <class T>
void rejectDuplicates(const std::vector<T>& items, std::string T::*name, const std::string& where,
                      const std::string& what)
{
    std::vector<std::string> names;
    for (const auto& item : items) names.push_back(item.*name);
    rejectDuplicates(names, where, what);
}

} // namespace procsim
