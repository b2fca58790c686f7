#include "plume/Terrain.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <set>
#include <sstream>

#include "common/Checked.hpp"
#include "common/Cli.hpp"
#include "common/Csv.hpp"

namespace procsim::plume
{

double EsriGrid::sample(double x, double y) const
{
    // continuous index of cell centres
    double fx = (x - xll) / cell - 0.5;
    double fy = (y - yll) / cell - 0.5;
    fx = std::clamp(fx, 0.0, static_cast<double>(ncols - 1));
    fy = std::clamp(fy, 0.0, static_cast<double>(nrows - 1));
    const int i0 = std::min(static_cast<int>(fx), std::max(ncols - 2, 0));
    const int j0 = std::min(static_cast<int>(fy), std::max(nrows - 2, 0));
    const int i1 = std::min(i0 + 1, ncols - 1);
    const int j1 = std::min(j0 + 1, nrows - 1);
    const double a = fx - i0;
    const double b = fy - j0;
    return (1 - a) * (1 - b) * at(i0, j0) + a * (1 - b) * at(i1, j0) + (1 - a) * b * at(i0, j1)
           + a * b * at(i1, j1);
}

namespace
{

std::string lower(std::string s)
{
    for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// "<path>: line <n>: ", the start of every message about one line
std::string atLine(const std::string& path, int lineNo)
{
    return path + ": line " + std::to_string(lineNo) + ": ";
}

// What the header of an ESRI ASCII grid says, before it is checked.
struct GridHeader
{
    EsriGrid grid; // ncols, nrows, lower-left corner, cell size
    std::optional<double> nodata;
    bool centre = false; // xllcenter/yllcenter given instead of the corner
    bool haveX = false, haveY = false, haveCell = false;
    std::streampos dataStart; // where the first elevation row starts
    int dataLine = 0;         // its line number; 0: no row after the header
};

// One header line "key value" (the value a finite number) into h.
void readHeaderKey(const std::string& path, int lineNo, const std::string& key, const std::string& text,
                   double value, GridHeader& h)
{
    const std::string k = lower(key);
    EsriGrid& g = h.grid;
    if (k == "ncols" || k == "nrows")
    {
        const auto n = parseInteger(text, 2, 100000);
        if (!n)
        {
            throw InputError(atLine(path, lineNo) + "header key '" + key
                             + "' expected a whole number from 2 to 100000, got '" + text + "'");
        }
        (k == "ncols" ? g.ncols : g.nrows) = static_cast<int>(*n);
    }
    else if (k == "xllcorner" || k == "xllcenter")
    {
        g.xll = value;
        h.haveX = true;
        h.centre = h.centre || k == "xllcenter";
    }
    else if (k == "yllcorner" || k == "yllcenter")
    {
        g.yll = value;
        h.haveY = true;
        h.centre = h.centre || k == "yllcenter";
    }
    else if (k == "cellsize")
    {
        g.cell = value;
        h.haveCell = true;
    }
    else if (k == "nodata_value")
    {
        h.nodata = value;
    }
    else
    {
        throw InputError(atLine(path, lineNo) + "unknown header key '" + key
                         + "' (expected ncols, nrows, xllcorner, yllcorner, cellsize, NODATA_value)");
    }
}

// The "key value" lines up to the first line that starts with a number.
GridHeader readHeader(std::istream& in, const std::string& path)
{
    GridHeader h;
    std::set<std::string> seenKeys;
    std::string line;
    int lineNo = 0;
    while (true)
    {
        h.dataStart = in.tellg();
        if (!std::getline(in, line)) break;
        ++lineNo;
        std::istringstream ss(line);
        std::string key;
        if (!(ss >> key)) continue;
        if (std::isdigit(static_cast<unsigned char>(key[0])) || key[0] == '-' || key[0] == '+'
            || key[0] == '.')
        {
            h.dataLine = lineNo;
            break;
        }
        std::string text, extra;
        ss >> text;
        const auto parsed = parseFinite(text);
        if (!parsed || (ss >> extra))
        {
            throw InputError(atLine(path, lineNo) + "header key '" + key + "' expected a finite number, got '"
                             + text + (extra.empty() ? "" : " " + extra) + "'");
        }
        if (!seenKeys.insert(lower(key)).second)
            throw InputError(atLine(path, lineNo) + "header key '" + key + "' is given twice");
        readHeaderKey(path, lineNo, key, text, *parsed, h);
    }
    return h;
}

// The header complete and in range; a centre given becomes the corner.
void checkHeader(const std::string& path, GridHeader& h)
{
    EsriGrid& g = h.grid;
    if (g.ncols < 2 || g.nrows < 2)
        throw InputError(path + ": header expected ncols and nrows >= 2 (ESRI ASCII grid)");
    if (!h.haveX || !h.haveY) throw InputError(path + ": header expected xllcorner and yllcorner");
    if (!h.haveCell || !(g.cell > 0 && g.cell <= 1e5))
        throw InputError(path + ": header expected cellsize > 0 and up to 1e5 m");
    if (!(std::fabs(g.xll) <= 1e7 && std::fabs(g.yll) <= 1e7))
        throw InputError(path + ": header expected xllcorner and yllcorner within 1e7 m of the origin");
    if (h.centre)
    {
        g.xll -= 0.5 * g.cell;
        g.yll -= 0.5 * g.cell;
    }
    if (h.dataLine == 0) throw InputError(path + ": no elevation rows after the header");
}

// One row of elevations into rows; the number of values read.
int readElevationRow(const std::string& path, int lineNo, const std::string& line,
                     const std::optional<double>& nodata, std::vector<double>& rows)
{
    std::istringstream ss(line);
    std::string tok;
    int n = 0;
    while (ss >> tok)
    {
        const auto parsed = parseFinite(tok);
        const bool nodataCell = parsed && nodata && *parsed == *nodata;
        if (!parsed || (!nodataCell && !(*parsed >= -1000 && *parsed <= 10000)))
        {
            throw InputError(atLine(path, lineNo) + "expected an elevation from -1000 to 10000 m, got '" + tok
                             + "'");
        }
        if (nodataCell)
        {
            throw InputError(atLine(path, lineNo)
                             + "NODATA cell in the terrain (fill every cell with an elevation)");
        }
        rows.push_back(*parsed);
        ++n;
    }
    return n;
}

// The elevation rows as written (north first), ncols values in each of nrows.
std::vector<double> readElevations(std::istream& in, const std::string& path, const GridHeader& h)
{
    const EsriGrid& g = h.grid;
    in.clear();
    in.seekg(h.dataStart);
    std::vector<double> rows;
    rows.reserve(static_cast<std::size_t>(g.ncols) * g.nrows);
    std::string line;
    int lineNo = h.dataLine - 1;
    int rowCount = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        const int n = readElevationRow(path, lineNo, line, h.nodata, rows);
        if (n == 0) continue;
        ++rowCount;
        if (n != g.ncols)
        {
            throw InputError(atLine(path, lineNo) + "expected " + std::to_string(g.ncols)
                             + " values (ncols), got " + std::to_string(n));
        }
    }
    if (rowCount != g.nrows)
    {
        throw InputError(path + ": expected " + std::to_string(g.nrows) + " rows (nrows), got "
                         + std::to_string(rowCount));
    }
    return rows;
}

} // namespace

EsriGrid readEsriGrid(const std::string& path)
{
    std::ifstream in = openInput(path, "a terrain grid file", "missing terrain file?");
    GridHeader h = readHeader(in, path);
    checkHeader(path, h);
    EsriGrid g = h.grid;
    checkMemory(static_cast<double>(g.ncols) * g.nrows, 2 * sizeof(double), path,
                "a terrain grid of " + std::to_string(g.ncols) + " x " + std::to_string(g.nrows) + " cells");
    const std::vector<double> rows = readElevations(in, path, h);
    // stored south first: row j of z is the j-th row from the south
    g.z.resize(rows.size());
    for (int r = 0; r < g.nrows; ++r)
    {
        const int south = g.nrows - 1 - r;
        std::copy(rows.begin() + static_cast<long>(r) * g.ncols,
                  rows.begin() + static_cast<long>(r + 1) * g.ncols,
                  g.z.begin() + static_cast<long>(south) * g.ncols);
    }
    return g;
}

void writeEsriGrid(const std::string& path, const EsriGrid& g)
{
    OutputFile file(path);
    std::ostream& out = file.out();
    out << "ncols " << g.ncols << "\nnrows " << g.nrows << "\nxllcorner " << g.xll << "\nyllcorner " << g.yll
        << "\ncellsize " << g.cell << "\nNODATA_value -9999\n";
    out << std::fixed << std::setprecision(2);
    for (int r = g.nrows - 1; r >= 0; --r)
    {
        for (int c = 0; c < g.ncols; ++c) out << (c ? " " : "") << g.at(c, r);
        out << '\n';
    }
    file.close();
}

} // namespace procsim::plume
