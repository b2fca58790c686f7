#include "common/Csv.hpp"

#include <cstdio>
#include <iomanip>
#include <sstream>

#include "common/Cli.hpp"

namespace procsim
{

std::string formatNumber(double v, int significant)
{
    std::ostringstream os;
    os << std::setprecision(significant) << v;
    return os.str();
}

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& header)
    : path_(path), out_(path + ".tmp")
{
    if (!out_) throw InputError(path + ": cannot be written");
    out_ << std::setprecision(10);
    row(header);
}

CsvWriter::~CsvWriter()
{
    if (!closed_)
    {
        out_.close();
        std::remove((path_ + ".tmp").c_str());   // unfinished: leave the old file
    }
}

void CsvWriter::row(const std::vector<double>& values)
{
    for (std::size_t i = 0; i < values.size(); ++i) out_ << (i ? "," : "") << values[i];
    out_ << '\n';
}

void CsvWriter::row(const std::vector<std::string>& values)
{
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        const bool quote = values[i].find(',') != std::string::npos;
        out_ << (i ? "," : "") << (quote ? "\"" : "") << values[i] << (quote ? "\"" : "");
    }
    out_ << '\n';
}

void CsvWriter::close()
{
    out_.close();
    std::rename((path_ + ".tmp").c_str(), path_.c_str());
    closed_ = true;
}

std::size_t CsvTable::column(const std::string& name, const std::string& file) const
{
    for (std::size_t i = 0; i < header.size(); ++i)
    {
        if (header[i] == name) return i;
    }
    throw InputError(file + ": column '" + name + "' is missing");
}

CsvTable readCsv(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot be read (missing file?)");
    CsvTable table;
    std::string line;
    std::size_t lineNo = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) cells.push_back(cell);
        if (table.header.empty())
        {
            table.header = cells;
            continue;
        }
        std::vector<double> row;
        for (const auto& c : cells)
        {
            try
            {
                row.push_back(std::stod(c));
            }
            catch (const std::exception&)
            {
                throw InputError(path + ": line " + std::to_string(lineNo)
                                 + ": expected a number, got '" + c + "'");
            }
        }
        if (row.size() != table.header.size())
        {
            throw InputError(path + ": line " + std::to_string(lineNo) + ": expected "
                             + std::to_string(table.header.size()) + " columns, got "
                             + std::to_string(row.size()));
        }
        table.rows.push_back(row);
    }
    return table;
}

} // namespace procsim
