/*---------------------------------------------------------------------------*\
    SpoutLab: particles as a ParaView time series.
\*---------------------------------------------------------------------------*/
#include "ParticleVtkSeries.H"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <utility>

namespace spoutlab
{

namespace
{

template<class Get>
void writeVectorArray
(
    std::ofstream& os, const char* name, std::size_t n, Get get
)
{
    os << "        <DataArray type=\"Float64\" Name=\"" << name
       << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3 v = get(i);
        os << ' ' << v.x << ' ' << v.y << ' ' << v.z << '\n';
    }
    os << "        </DataArray>\n";
}

} // namespace


ParticleVtkSeries::ParticleVtkSeries
(
    const std::string& directory,
    const std::string& name
)
:
    directory_(directory),
    name_(name)
{}


void ParticleVtkSeries::write
(
    double time,
    const std::string& timeName,
    const std::vector<Particle>& particles,
    const std::vector<std::pair<std::string, std::vector<Vec3>>>& vectors,
    const std::vector<std::pair<std::string, std::vector<double>>>& scalars
) const
{
    std::filesystem::create_directories(directory_);
    const std::string file = directory_ + "/" + name_ + "_" + timeName + ".vtp";
    const std::size_t n = particles.size();

    // write to a temporary name first: an interrupted run never leaves a
    // truncated file that ParaView would choke on
    {
        std::ofstream os(file + ".tmp");
        os << std::setprecision(9);
        os << "<?xml version=\"1.0\"?>\n"
           << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           << "  <PolyData>\n"
           << "    <FieldData>\n"
           << "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\"> "
           << time << " </DataArray>\n"
           << "    </FieldData>\n"
           << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
           << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
           << "      <Points>\n";
        writeVectorArray(os, "position", n, [&](std::size_t i) { return particles[i].x; });
        os << "      </Points>\n"
           << "      <PointData Scalars=\"radius\" Vectors=\"velocity\">\n"
           << "        <DataArray type=\"Int64\" Name=\"id\" format=\"ascii\">\n";
        for (const auto& p : particles) os << ' ' << p.id << '\n';
        os << "        </DataArray>\n"
           << "        <DataArray type=\"Float64\" Name=\"radius\" format=\"ascii\">\n";
        for (const auto& p : particles) os << ' ' << p.radius << '\n';
        os << "        </DataArray>\n";
        writeVectorArray(os, "velocity", n, [&](std::size_t i) { return particles[i].v; });
        for (const auto& named : vectors)
        {
            const std::vector<Vec3>& v = named.second;
            writeVectorArray
            (
                os, named.first.c_str(), n,
                [&](std::size_t i) { return i < v.size() ? v[i] : Vec3{}; }
            );
        }
        for (const auto& named : scalars)
        {
            const std::vector<double>& v = named.second;
            os << "        <DataArray type=\"Float64\" Name=\"" << named.first
               << "\" format=\"ascii\">\n";
            for (std::size_t i = 0; i < n; ++i) os << ' ' << (i < v.size() ? v[i] : 0.0) << '\n';
            os << "        </DataArray>\n";
        }
        os << "      </PointData>\n"
           << "      <Verts>\n"
           << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
        for (std::size_t i = 0; i < n; ++i) os << ' ' << i << '\n';
        os << "        </DataArray>\n"
           << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
        for (std::size_t i = 0; i < n; ++i) os << ' ' << i + 1 << '\n';
        os << "        </DataArray>\n"
           << "      </Verts>\n"
           << "    </Piece>\n"
           << "  </PolyData>\n"
           << "</VTKFile>\n";
    }
    std::filesystem::rename(file + ".tmp", file);
    writeCollection();
}


void ParticleVtkSeries::writeCollection() const
{
    // every <name>_<time>.vtp on disk, ordered by time
    std::vector<std::pair<double, std::string>> steps;
    const std::string prefix = name_ + "_";
    for (const auto& entry : std::filesystem::directory_iterator(directory_))
    {
        const std::string file = entry.path().filename().string();
        if (file.size() <= prefix.size() + 4 || file.rfind(prefix, 0) != 0) continue;
        if (file.substr(file.size() - 4) != ".vtp") continue;
        const std::string t = file.substr(prefix.size(), file.size() - prefix.size() - 4);
        try { steps.emplace_back(std::stod(t), file); }
        catch (const std::exception&) {}
    }
    std::sort(steps.begin(), steps.end());

    const std::string pvd = directory_ + "/" + name_ + ".pvd";
    {
        std::ofstream os(pvd + ".tmp");
        os << std::setprecision(12)
           << "<?xml version=\"1.0\"?>\n"
           << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           << "  <Collection>\n";
        for (const auto& s : steps)
        {
            os << "    <DataSet timestep=\"" << s.first
               << "\" group=\"\" part=\"0\" file=\"" << s.second << "\"/>\n";
        }
        os << "  </Collection>\n</VTKFile>\n";
    }
    std::filesystem::rename(pvd + ".tmp", pvd);
}

} // namespace spoutlab
