#include "plume/Terrain.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
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

} // namespace

EsriGrid readEsriGrid(const std::string& path)
{
    std::ifstream in = openInput(path, "a terrain grid file", "missing terrain file?");

    EsriGrid g;
    bool haveNodata = false;
    double nodata = -9999;
    bool centre = false;
    bool haveX = false, haveY = false, haveCell = false;
    std::set<std::string> seenKeys;
    std::string line;
    int lineNo = 0;
    std::streampos dataStart = in.tellg();
    int dataLine = 0;
    // header: "key value" lines until the first line starting with a number
    while (true)
    {
        dataStart = in.tellg();
        if (!std::getline(in, line)) break;
        ++lineNo;
        std::istringstream ss(line);
        std::string key;
        if (!(ss >> key)) continue;
        if (std::isdigit(static_cast<unsigned char>(key[0])) || key[0] == '-' || key[0] == '+'
            || key[0] == '.')
        {
            dataLine = lineNo;
            break;
        }
        std::string text, extra;
        ss >> text;
        const auto parsed = parseFinite(text);
        if (!parsed || (ss >> extra))
        {
            throw InputError(path + ": line " + std::to_string(lineNo) + ": header key '" + key
                             + "' expected a finite number, got '" + text + (extra.empty() ? "" : " " + extra)
                             + "'");
        }
        const double value = *parsed;
        const std::string k = lower(key);
        if (!seenKeys.insert(k).second)
        {
            throw InputError(path + ": line " + std::to_string(lineNo) + ": header key '" + key
                             + "' is given twice");
        }
        if (k == "ncols" || k == "nrows")
        {
            const auto n = parseInteger(text, 2, 100000);
            if (!n)
            {
                throw InputError(path + ": line " + std::to_string(lineNo) + ": header key '" + key
                                 + "' expected a whole number from 2 to 100000, got '" + text + "'");
            }
            (k == "ncols" ? g.ncols : g.nrows) = static_cast<int>(*n);
        }
        else if (k == "xllcorner")
        {
            g.xll = value;
            haveX = true;
        }
        else if (k == "yllcorner")
        {
            g.yll = value;
            haveY = true;
        }
        else if (k == "xllcenter")
        {
            g.xll = value;
            haveX = true;
            centre = true;
        }
        else if (k == "yllcenter")
        {
            g.yll = value;
            haveY = true;
            centre = true;
        }
        else if (k == "cellsize")
        {
            g.cell = value;
            haveCell = true;
        }
        else if (k == "nodata_value")
        {
            nodata = value;
            haveNodata = true;
        }
        else
        {
            throw InputError(path + ": line " + std::to_string(lineNo) + ": unknown header key '" + key
                             + "' (expected ncols, nrows, xllcorner, yllcorner, cellsize, "
                               "NODATA_value)");
        }
    }
    if (g.ncols < 2 || g.nrows < 2)
        throw InputError(path + ": header expected ncols and nrows >= 2 (ESRI ASCII grid)");
    if (!haveX || !haveY) throw InputError(path + ": header expected xllcorner and yllcorner");
    if (!haveCell || !(g.cell > 0 && g.cell <= 1e5))
        throw InputError(path + ": header expected cellsize > 0 and up to 1e5 m");
    if (!(std::fabs(g.xll) <= 1e7 && std::fabs(g.yll) <= 1e7))
        throw InputError(path + ": header expected xllcorner and yllcorner within 1e7 m of the origin");
    if (centre)
    {
        g.xll -= 0.5 * g.cell;
        g.yll -= 0.5 * g.cell;
    }
    if (dataLine == 0) throw InputError(path + ": no elevation rows after the header");

    checkMemory(static_cast<double>(g.ncols) * g.nrows, 2 * sizeof(double), path,
                "a terrain grid of " + std::to_string(g.ncols) + " x " + std::to_string(g.nrows) + " cells");
    in.clear();
    in.seekg(dataStart);
    lineNo = dataLine - 1;
    std::vector<double> rows; // as written: north first
    rows.reserve(static_cast<std::size_t>(g.ncols) * g.nrows);
    int rowCount = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        std::istringstream ss(line);
        std::string tok;
        int n = 0;
        bool any = false;
        while (ss >> tok)
        {
            any = true;
            const auto parsed = parseFinite(tok);
            const bool nodataCell = parsed && haveNodata && *parsed == nodata;
            if (!parsed || (!nodataCell && !(*parsed >= -1000 && *parsed <= 10000)))
            {
                throw InputError(path + ": line " + std::to_string(lineNo)
                                 + ": expected an elevation from -1000 to 10000 m, got '" + tok + "'");
            }
            const double v = *parsed;
            if (haveNodata && v == nodata)
            {
                throw InputError(path + ": line " + std::to_string(lineNo)
                                 + ": NODATA cell in the terrain (fill every cell with an elevation)");
            }
            rows.push_back(v);
            ++n;
        }
        if (!any) continue;
        ++rowCount;
        if (n != g.ncols)
        {
            throw InputError(path + ": line " + std::to_string(lineNo) + ": expected "
                             + std::to_string(g.ncols) + " values (ncols), got " + std::to_string(n));
        }
    }
    if (rowCount != g.nrows)
    {
        throw InputError(path + ": expected " + std::to_string(g.nrows) + " rows (nrows), got "
                         + std::to_string(rowCount));
    }
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
