#include "common/Csv.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <sstream>
#include <utility>

#include "common/Checked.hpp"
#include "common/Cli.hpp"

namespace procsim
{

namespace
{

struct Batch
{
    std::vector<std::pair<std::string, std::string>> staged; // tmp, final
    std::vector<std::function<void()>> deferred;
};

std::mutex batchMutex;
std::unique_ptr<Batch> current; // the open batch (one at a time: main's)

void putInPlace(const std::string& tmp, const std::string& path)
{
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
    {
        std::remove(tmp.c_str());
        throw InputError(path + ": cannot be written (rename from its temporary failed)");
    }
}

bool isMissing(const std::string& cell)
{
    std::string t;
    for (char ch : cell)
    {
        if (ch != ' ' && ch != '\t') t += ch;
    }
    return t.empty() || t == "nan" || t == "NaN";
}

} // namespace

void createOutputDirectory(const std::string& dir)
{
    namespace fs = std::filesystem;
    fs::create_directories(dir);
    if (!fs::is_directory(dir))
        throw fs::filesystem_error("not a directory", dir, std::make_error_code(std::errc::not_a_directory));
}

OutputBatch::OutputBatch()
{
    std::lock_guard<std::mutex> lock(batchMutex);
    current = std::make_unique<Batch>();
}

OutputBatch::~OutputBatch()
{
    std::lock_guard<std::mutex> lock(batchMutex);
    if (!current) return;
    for (const auto& [tmp, path] : current->staged) std::remove(tmp.c_str());
    current.reset();
}

void OutputBatch::commit()
{
    std::unique_ptr<Batch> b;
    {
        std::lock_guard<std::mutex> lock(batchMutex);
        b = std::move(current);
    }
    if (!b) return;
    for (std::size_t i = 0; i < b->staged.size(); ++i)
    {
        try
        {
            putInPlace(b->staged[i].first, b->staged[i].second);
        }
        catch (...)
        {
            for (std::size_t j = i + 1; j < b->staged.size(); ++j) std::remove(b->staged[j].first.c_str());
            throw;
        }
    }
    for (auto& work : b->deferred) work();
}

bool OutputBatch::open()
{
    std::lock_guard<std::mutex> lock(batchMutex);
    return current != nullptr;
}

void OutputBatch::stage(const std::string& tmp, const std::string& path)
{
    std::unique_lock<std::mutex> lock(batchMutex);
    if (current)
    {
        for (const auto& staged : current->staged)
        {
            if (staged.second == path)
                throw InputError(path + ": would be written twice by one run (two equal names?)");
        }
        current->staged.emplace_back(tmp, path);
        return;
    }
    lock.unlock();
    putInPlace(tmp, path);
}

void OutputBatch::defer(std::function<void()> work)
{
    std::unique_lock<std::mutex> lock(batchMutex);
    if (current)
    {
        current->deferred.push_back(std::move(work));
        return;
    }
    lock.unlock();
    work();
}

OutputFile::OutputFile(const std::string& path) : path_(path), out_(path + ".tmp")
{
    if (!out_) throw InputError(path + ": cannot be written");
}

OutputFile::~OutputFile()
{
    if (!closed_)
    {
        out_.close();
        std::remove((path_ + ".tmp").c_str()); // unfinished: leave the old file
    }
}

void OutputFile::close()
{
    out_.close();
    closed_ = true;
    if (!out_)
    {
        std::remove((path_ + ".tmp").c_str());
        throw InputError(path_ + ": cannot be written (disk full?)");
    }
    OutputBatch::stage(path_ + ".tmp", path_);
}

void writeTextFile(const std::string& path, const std::string& text)
{
    OutputFile f(path);
    f.out() << text;
    f.close();
}

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& header)
    : file_(path), header_(header)
{
    row(header);
}

void CsvWriter::row(const std::vector<double>& values)
{
    // nan may stand for "not available"; an infinity is always an input out of range
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        if (std::isinf(values[i]))
        {
            throw InputError(file_.path() + ": column '"
                             + (i < header_.size() ? header_[i] : std::to_string(i + 1))
                             + "' would hold an infinite result (an input far out of range?)");
        }
    }
    std::ostream& out = file_.out();
    for (std::size_t i = 0; i < values.size(); ++i) out << (i ? "," : "") << formatNumber(values[i], 10);
    out << '\n';
}

void CsvWriter::row(const std::vector<std::string>& values)
{
    std::ostream& out = file_.out();
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        const bool quote = values[i].find(',') != std::string::npos;
        out << (i ? "," : "") << (quote ? "\"" : "") << values[i] << (quote ? "\"" : "");
    }
    out << '\n';
}

void CsvWriter::close()
{
    file_.close();
}

std::size_t CsvTable::column(const std::string& name, const std::string& file) const
{
    for (std::size_t i = 0; i < header.size(); ++i)
    {
        if (header[i] == name) return i;
    }
    throw InputError(file + ": column '" + name + "' is missing");
}

void CsvTable::rejectUnknownColumns(const std::vector<std::string>& known, const std::string& file) const
{
    for (const auto& name : header)
    {
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        throw InputError(file + ": line " + std::to_string(headerLine) + ": unknown column '" + name
                         + "' (expected one of: " + list + ")");
    }
}

CsvTable readCsv(const std::string& path, bool allowMissing)
{
    std::ifstream in = openInput(path, "a CSV file");
    CsvTable table;
    std::string line;
    std::size_t lineNo = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) cells.push_back(cell);
        if (!line.empty() && line.back() == ',') cells.emplace_back();
        const std::string where = path + ": line " + std::to_string(lineNo);
        if (table.header.empty())
        {
            rejectDuplicates(cells, where, "column");
            table.header = cells;
            table.headerLine = lineNo;
            continue;
        }
        if (cells.size() != table.header.size())
        {
            throw InputError(where + ": expected " + std::to_string(table.header.size()) + " columns, got "
                             + std::to_string(cells.size()));
        }
        std::vector<double> row;
        for (std::size_t i = 0; i < cells.size(); ++i)
        {
            const auto v = parseFinite(cells[i]);
            if (!v && allowMissing && isMissing(cells[i]))
            {
                row.push_back(std::numeric_limits<double>::quiet_NaN());
                continue;
            }
            if (!v)
            {
                throw InputError(where + ": column '" + table.header[i] + "' expected a finite number, got '"
                                 + cells[i] + "'");
            }
            row.push_back(*v);
        }
        table.rows.push_back(row);
        table.lines.push_back(lineNo);
    }
    return table;
}

} // namespace procsim
