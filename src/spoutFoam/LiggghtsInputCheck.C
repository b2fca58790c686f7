/*---------------------------------------------------------------------------*\
    SpoutLab: a check of a LIGGGHTS input before LIGGGHTS reads it.
\*---------------------------------------------------------------------------*/
#include "LiggghtsInputCheck.H"

#include "InputError.hpp"

#include <cctype>
#include <fstream>
#include <sstream>
#include <vector>

namespace spoutlab
{

namespace
{

bool readable(const std::string& path)
{
    std::ifstream f(path);
    return f.good();
}

class IncludeCheck
{
public:
    IncludeCheck
    (
        const std::string& input,
        const std::map<std::string, std::string>& variables
    )
    :
        input_(input), given_(variables), vars_(variables)
    {}

    //- Whether a command of the scripts (includes followed) refers to the
    //  variable name, as ${name} or v_name; valid after check().
    bool uses(const std::string& name) const
    {
        for (const std::string& text : commands_)
        {
            if (text.find("${" + name + "}") != std::string::npos) return true;
            for
            (
                std::size_t at = text.find("v_" + name);
                at != std::string::npos;
                at = text.find("v_" + name, at + 1)
            )
            {
                const std::size_t end = at + 2 + name.size();
                const bool wordStart =
                    at == 0 || !(std::isalnum(text[at - 1]) || text[at - 1] == '_');
                const bool wordEnd =
                    end == text.size() || !(std::isalnum(text[end]) || text[end] == '_');
                if (wordStart && wordEnd) return true;
            }
        }
        return false;
    }

    void check(const std::string& script, int depth = 0)
    {
        std::ifstream in(script);
        int lineNo = 0, firstLine = 0;
        std::string line, command;
        while (std::getline(in, line))
        {
            ++lineNo;
            if (command.empty()) firstLine = lineNo;
            command += line;
            // '&' at the end continues the command on the next line
            const auto last = command.find_last_not_of(" \t\r");
            if (last != std::string::npos && command[last] == '&')
            {
                command.erase(last);
                command += ' ';
                continue;
            }
            process(script, firstLine, command, depth);
            command.clear();
        }
        if (!command.empty()) process(script, firstLine, command, depth);
    }

private:
    std::string input_;
    std::map<std::string, std::string> given_;   // -var: never redefined
    std::map<std::string, std::string> vars_;
    std::vector<std::string> commands_;   // as written, without comments

    static std::string withoutComment(const std::string& line)
    {
        char quote = 0;
        for (std::size_t i = 0; i < line.size(); ++i)
        {
            const char c = line[i];
            if (quote) { if (c == quote) quote = 0; }
            else if (c == '"' || c == '\'') quote = c;
            else if (c == '#') return line.substr(0, i);
        }
        return line;
    }

    // ${name} and $x replaced; an unknown name is kept as it is
    std::string expand(const std::string& text) const
    {
        std::string out;
        for (std::size_t i = 0; i < text.size(); ++i)
        {
            if (text[i] != '$' || i + 1 == text.size())
            {
                out += text[i];
                continue;
            }
            std::string name;
            std::size_t end = i + 1;
            if (text[i + 1] == '{')
            {
                const std::size_t close = text.find('}', i + 2);
                if (close == std::string::npos) { out += text.substr(i); break; }
                name = text.substr(i + 2, close - i - 2);
                end = close;
            }
            else if (text[i + 1] != '(')
            {
                name = text.substr(i + 1, 1);
            }
            const auto v = vars_.find(name);
            if (name.empty() || v == vars_.end())
            {
                out += text[i];
                continue;
            }
            out += v->second;
            i = end;
        }
        return out;
    }

    static std::vector<std::string> words(const std::string& text)
    {
        std::vector<std::string> out;
        std::istringstream is(text);
        for (std::string w; is >> w;)
        {
            if (w.size() >= 2 && (w[0] == '"' || w[0] == '\'') && w.back() == w[0])
            {
                w = w.substr(1, w.size() - 2);
            }
            out.push_back(w);
        }
        return out;
    }

    void process
    (
        const std::string& script, int lineNo, const std::string& raw, int depth
    )
    {
        commands_.push_back(withoutComment(raw));
        const std::vector<std::string> w = words(expand(commands_.back()));
        if (w.size() >= 4 && w[0] == "variable")
        {
            // LIGGGHTS skips an index variable that exists (e.g. from -var)
            // and replaces a string one
            if (given_.count(w[1])) return;
            if (w[2] == "index" && !vars_.count(w[1])) vars_[w[1]] = w[3];
            else if (w[2] == "string") vars_[w[1]] = w[3];
            else if (w[2] != "index") vars_.erase(w[1]);  // not followed here
        }
        else if (w.size() >= 2 && w[0] == "variable" && w[1] != "")
        {
            if (!given_.count(w[1])) vars_.erase(w[1]);
        }
        else if (w.size() == 2 && w[0] == "include")
        {
            const std::string& file = w[1];
            if (file.find('$') != std::string::npos) return;   // not resolvable
            if (!readable(file))
            {
                throw InputError
                (
                    "LIGGGHTS input '" + input_ + "': 'include " + file + "' ("
                  + (script == input_ ? "" : script + ", ") + "line "
                  + std::to_string(lineNo) + ") names a missing file"
                );
            }
            if (depth < 32) check(file, depth + 1);   // include loops end here
        }
    }
};

} // namespace

void checkIncludes
(
    const std::string& inputFile,
    const std::map<std::string, std::string>& variables
)
{
    IncludeCheck(inputFile, variables).check(inputFile);
}


bool usesVariable
(
    const std::string& inputFile,
    const std::map<std::string, std::string>& variables,
    const std::string& name
)
{
    IncludeCheck scripts(inputFile, variables);
    scripts.check(inputFile);
    return scripts.uses(name);
}

} // namespace spoutlab
