#pragma once
// Output files and CSV input.
//
// Every output is written to "<path>.tmp" and renamed when complete.  While
// an OutputBatch is open (main opens one around each command) the renames
// wait until the batch commits, that is until the whole command succeeded:
// a command that fails part-way removes its temporaries and leaves every
// file of an earlier run exactly as it was.  Without a batch (library use,
// unit tests) each file is put in place as soon as it is closed.
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "common/Format.hpp"

namespace procsim
{

// The one way an output directory is made: with its parents
// (std::filesystem).  Something in the way that is not a directory throws
// std::filesystem::filesystem_error, which runGuarded reports as
// "<command>: cannot create or use '<dir>': <reason>".
void createOutputDirectory(const std::string& dir);

class OutputBatch
{
public:
    OutputBatch();
    ~OutputBatch(); // without commit(): remove every staged temporary
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;
    void commit(); // rename every staged file into place, then run deferred work

    // Is a batch open?  Staged renames and deferred work go to it.
    static bool open();
    static void stage(const std::string& tmp, const std::string& path);
    static void defer(std::function<void()> work);
};

// One output file written through its temporary.
class OutputFile
{
public:
    explicit OutputFile(const std::string& path); // throws InputError if it cannot be created
    ~OutputFile();                                // not closed: remove the temporary
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    std::ostream& out() { return out_; }
    const std::string& path() const { return path_; }
    void close(); // finish: put in place now, or when the batch commits

private:
    std::string path_;
    std::ofstream out_;
    bool closed_ = false;
};

// Write a whole small text file through OutputFile.
void writeTextFile(const std::string& path, const std::string& text);

// CSV output: a header row with units in the column names, then rows.  A
// numeric row holding an infinity is refused (InputError): no result file
// ever shows inf.
class CsvWriter
{
public:
    CsvWriter(const std::string& path, const std::vector<std::string>& header);

    void row(const std::vector<double>& values);
    void row(const std::vector<std::string>& values);
    void close();

private:
    OutputFile file_;
    std::vector<std::string> header_;
};

// Read a CSV with a header row: column names and numeric rows.  Every cell
// must be a finite number filling the whole cell ("12.5abc" is refused), and
// a column name may appear only once.  With allowMissing, a cell "nan" or an
// empty cell means "not given" and is read as NaN for the caller to handle.
struct CsvTable
{
    std::vector<std::string> header;
    std::vector<std::vector<double>> rows;
    std::size_t headerLine = 0;     // file line (from 1) of the header
    std::vector<std::size_t> lines; // file line of each row, for messages
    std::size_t column(const std::string& name, const std::string& file) const; // throws InputError
    // A column not in `known` -> InputError naming the first one and the header's line.
    void rejectUnknownColumns(const std::vector<std::string>& known, const std::string& file) const;
};
CsvTable readCsv(const std::string& path, bool allowMissing = false);

} // namespace procsim
