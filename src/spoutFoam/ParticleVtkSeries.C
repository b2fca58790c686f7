/*---------------------------------------------------------------------------*\
    SpoutLab: particles as a ParaView time series.
\*---------------------------------------------------------------------------*/
#include "ParticleVtkSeries.H"

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <functional>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt64Array.h>

#include "VtkXmlFile.hpp"

namespace spoutlab
{

namespace
{

// A per-particle vector; a shorter list (a rank that sent none) reads as zero
vtkSmartPointer<vtkFloatArray> vectorArray
(
    const std::string& name, const std::vector<Vec3>& v, std::size_t n
)
{
    auto a = vtkxml::floatArray(name, 3, n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3 x = i < v.size() ? v[i] : Vec3{};
        a->SetTypedTuple(static_cast<vtkIdType>(i), std::array<float, 3>{
            float(x.x), float(x.y), float(x.z)}.data());
    }
    return a;
}


vtkSmartPointer<vtkFloatArray> scalarArray
(
    const std::string& name, const std::vector<double>& v, std::size_t n
)
{
    auto a = vtkxml::floatArray(name, 1, n);
    for (std::size_t i = 0; i < n; ++i)
    {
        a->SetValue(static_cast<vtkIdType>(i), float(i < v.size() ? v[i] : 0.0));
    }
    return a;
}


// Where the particles are and how big: geometry stays in double, so volumes
// and cell membership computed from the file are those of the run
void addGeometry(vtkPolyData& poly, const std::vector<Particle>& particles)
{
    const std::size_t n = particles.size();
    auto x = vtkxml::doubleArray("position", 3, n);
    auto radius = vtkxml::doubleArray("radius", 1, n);
    vtkNew<vtkTypeInt64Array> id;
    id->SetName("id");
    id->SetNumberOfTuples(static_cast<vtkIdType>(n));
    vtkNew<vtkCellArray> verts;   // one vertex cell each: ParaView draws them
    verts->AllocateExact(static_cast<vtkIdType>(n), static_cast<vtkIdType>(n));
    for (std::size_t i = 0; i < n; ++i)
    {
        const Particle& p = particles[i];
        const auto k = static_cast<vtkIdType>(i);
        x->SetTuple3(k, p.x.x, p.x.y, p.x.z);
        radius->SetValue(k, p.radius);
        id->SetValue(k, p.id);
        verts->InsertNextCell(1, &k);
    }
    vtkNew<vtkPoints> points;
    points->SetData(x);
    poly.SetPoints(points);
    poly.SetVerts(verts);
    poly.GetPointData()->AddArray(id);
    poly.GetPointData()->SetScalars(radius);
}

// Write to a temporary name first: an interrupted run never leaves a
// truncated file that ParaView would choke on
void writeReplacing
(
    const std::string& path, const std::function<void(const std::string&)>& writeTo
)
{
    writeTo(path + ".tmp");
    std::filesystem::rename(path + ".tmp", path);
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
    const std::size_t n = particles.size();
    vtkNew<vtkPolyData> poly;
    addGeometry(*poly, particles);

    std::vector<Vec3> v(n);
    std::transform(particles.begin(), particles.end(), v.begin(), [](const Particle& p) { return p.v; });
    poly->GetPointData()->SetVectors(vectorArray("velocity", v, n));
    for (const auto& [name, values] : vectors)
    {
        poly->GetPointData()->AddArray(vectorArray(name, values, n));
    }
    for (const auto& [name, values] : scalars)
    {
        poly->GetPointData()->AddArray(scalarArray(name, values, n));
    }

    // ParaView shows the simulation time of a file opened on its own
    auto timeValue = vtkxml::doubleArray("TimeValue", 1, 1);
    timeValue->SetValue(0, time);
    poly->GetFieldData()->AddArray(timeValue);

    std::filesystem::create_directories(directory_);
    writeReplacing
    (
        directory_ + "/" + name_ + "_" + timeName + ".vtp",
        [&](const std::string& file) { vtkxml::write(poly, file); }
    );
    writeCollection();
}


void ParticleVtkSeries::writeCollection() const
{
    // every <name>_<time>.vtp on disk, ordered by time
    vtkxml::CollectionEntries steps;
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
    writeReplacing
    (
        directory_ + "/" + name_ + ".pvd",
        [&](const std::string& file) { std::ofstream(file) << vtkxml::collection(steps); }
    );
}

} // namespace spoutlab
