#pragma once
// CSV output: a header row with units in the column names, then rows.
// Written to "<path>.tmp" and renamed on close, so an interrupted run never
// leaves a half-written result in place of a good one.
#include <fstream>
#include <string>
#include <vector>

namespace procsim
{

// v with `significant` digits, as CSV cells and summaries print numbers.
std::string formatNumber(double v, int significant = 6);

class CsvWriter
{
public:
    CsvWriter(const std::string& path, const std::vector<std::string>& header);
    ~CsvWriter();
    CsvWriter(const CsvWriter&) = delete;
    CsvWriter& operator=(const CsvWriter&) = delete;

    void row(const std::vector<double>& values);
    void row(const std::vector<std::string>& values);
    void close();   // rename into place

private:
    std::string path_;
    std::ofstream out_;
    bool closed_ = false;
};

// Read a CSV with a header row: column names and numeric rows.
struct CsvTable
{
    std::vector<std::string> header;
    std::vector<std::vector<double>> rows;
    std::size_t column(const std::string& name, const std::string& file) const;  // throws InputError
};
CsvTable readCsv(const std::string& path);

} // namespace procsim
