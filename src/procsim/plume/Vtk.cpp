#include "plume/Vtk.hpp"

#include <algorithm>
#include <iomanip>

#include "common/Cli.hpp"
#include "common/Csv.hpp"
#include "plume/Eulerian.hpp"

namespace procsim::plume
{

void writeVts(const std::string& path, const TerrainGrid& g, const std::string& fieldName,
              const std::vector<double>& v)
{
    OutputFile file(path);
    std::ostream& out = file.out();
    const int nx = g.nx, ny = g.ny, nz = g.nz;
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"StructuredGrid\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n<StructuredGrid WholeExtent=\"0 "
        << nx << " 0 " << ny << " 0 " << nz << "\">\n<Piece Extent=\"0 " << nx << " 0 " << ny
        << " 0 " << nz << "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                          "format=\"ascii\">\n";
    out << std::setprecision(8);
    // terrain at the column corners: mean of the adjacent column centres
    auto corner = [&](int i, int j) {
        double s = 0;
        int n = 0;
        for (int dj = -1; dj <= 0; ++dj)
            for (int di = -1; di <= 0; ++di)
            {
                const int ii = i + di, jj = j + dj;
                if (ii < 0 || jj < 0 || ii >= nx || jj >= ny) continue;
                s += g.hc[g.col(ii, jj)];
                ++n;
            }
        return s / n;
    };
    std::vector<double> hcorner(static_cast<std::size_t>(nx + 1) * (ny + 1));
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) hcorner[j * (nx + 1) + i] = corner(i, j);
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i)
            {
                const double h = hcorner[j * (nx + 1) + i];
                out << g.x0 + i * g.dx << ' ' << g.y0 + j * g.dy << ' '
                    << h + (g.zTop - h) * g.fFace[k] << '\n';
            }
    out << "</DataArray>\n</Points>\n<CellData Scalars=\"" << fieldName
        << "\">\n<DataArray type=\"Float64\" Name=\"" << fieldName << "\" format=\"ascii\">\n";
    out << std::setprecision(6);
    for (std::size_t n = 0; n < v.size(); ++n) out << v[n] << ((n % 8 == 7) ? '\n' : ' ');
    out << "\n</DataArray>\n</CellData>\n</Piece>\n</StructuredGrid>\n</VTKFile>\n";
    file.close();
}

void writePvd(const std::string& path, const std::vector<std::pair<double, std::string>>& entries)
{
    OutputFile file(path);
    std::ostream& out = file.out();
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (const auto& e : entries)
        out << "  <DataSet timestep=\"" << e.first << "\" file=\"" << e.second << "\"/>\n";
    out << "</Collection>\n</VTKFile>\n";
    file.close();
}

} // namespace procsim::plume
