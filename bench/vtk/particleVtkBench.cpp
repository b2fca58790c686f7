// particleVtkBench [FRAME.vtp] [--repeat R] [--dir DIR]
//
// One particle frame written as spoutFoam writes it (ParticleVtkSeries:
// binary, zlib, appended) and, side by side, as VTK's ASCII XML of the same
// arrays; prints file sizes and the best-of-R write times.  The frame is read
// from FRAME.vtp (any particle file, e.g. an ASCII one of an older run), else
// 26 000 particles are made up at random (fixed seed) in the spouted bed.
// Prints figures only (bench/README.md).
#include <chrono>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include "ParticleVtkSeries.H"

namespace fs = std::filesystem;
using namespace spoutlab;

namespace
{

struct Frame
{
    std::vector<Particle> particles;
    std::vector<std::pair<std::string, std::vector<Vec3>>> vectors;
    std::vector<std::pair<std::string, std::vector<double>>> scalars;
};

Frame randomFrame(std::size_t n)
{
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> x(-0.2475, 0.2475), y(0.0, 0.04), z(0.0, 0.6);
    std::normal_distribution<double> v(0.0, 0.3), f(0.0, 3e-4);
    Frame frame;
    std::vector<Vec3> fluid(n), drag(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        Particle p;
        p.id = long(i) + 1;
        p.x = {x(rng), y(rng), z(rng)};
        p.v = {v(rng), v(rng), v(rng)};
        p.radius = 0.004;
        frame.particles.push_back(p);
        fluid[i] = {f(rng), f(rng), f(rng)};
        drag[i] = {f(rng), f(rng), f(rng)};
    }
    frame.vectors = {{"fluidForce", fluid}, {"dragForce", drag}};
    return frame;
}

Vec3 tuple3(vtkDataArray* a, vtkIdType i)
{
    const double* t = a->GetTuple3(i);
    return {t[0], t[1], t[2]};
}

Frame readFrame(const std::string& file)
{
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkPolyData* poly = reader->GetOutput();
    vtkPointData* pd = poly->GetPointData();
    Frame frame;
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
    {
        Particle p;
        double x[3];
        poly->GetPoint(i, x);
        p.x = {x[0], x[1], x[2]};
        p.id = long(pd->GetArray("id")->GetTuple1(i));
        p.radius = pd->GetArray("radius")->GetTuple1(i);
        p.v = tuple3(pd->GetArray("velocity"), i);
        frame.particles.push_back(p);
    }
    for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
    {
        vtkDataArray* array = pd->GetArray(a);
        const std::string name = array->GetName();
        if (name == "id" || name == "radius" || name == "velocity") continue;
        if (array->GetNumberOfComponents() == 3)
        {
            std::vector<Vec3> v(poly->GetNumberOfPoints());
            for (vtkIdType i = 0; i < vtkIdType(v.size()); ++i) v[i] = tuple3(array, i);
            frame.vectors.emplace_back(name, v);
        }
        else
        {
            std::vector<double> v(poly->GetNumberOfPoints());
            for (vtkIdType i = 0; i < vtkIdType(v.size()); ++i) v[i] = array->GetTuple1(i);
            frame.scalars.emplace_back(name, v);
        }
    }
    return frame;
}

template <class Write>
double bestSeconds(int repeat, Write write)
{
    double best = 1e300;
    for (int r = 0; r < repeat; ++r)
    {
        const auto start = std::chrono::steady_clock::now();
        write();
        best =
            std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return best;
}

void report(const char* what, const fs::path& file, double seconds)
{
    std::cout << what << ": " << fs::file_size(file) / 1e6 << " MB, " << seconds * 1e3 << " ms\n";
}

} // namespace

int main(int argc, char** argv)
{
    std::string input;
    int repeat = 5;
    fs::path dir = fs::temp_directory_path() / "particleVtkBench";
    for (int a = 1; a < argc; ++a)
    {
        const std::string arg = argv[a];
        if (arg == "--repeat" && a + 1 < argc)
            repeat = std::stoi(argv[++a]);
        else if (arg == "--dir" && a + 1 < argc)
            dir = argv[++a];
        else
            input = arg;
    }
    const Frame frame = input.empty() ? randomFrame(26000) : readFrame(input);
    fs::create_directories(dir);
    std::cout << frame.particles.size() << " particles, " << 2 + frame.vectors.size() + frame.scalars.size()
              << " point arrays besides the id\n";
    if (!input.empty()) std::cout << "input file: " << fs::file_size(input) / 1e6 << " MB\n";

    const ParticleVtkSeries series(dir.string(), "particles");
    const double binary =
        bestSeconds(repeat, [&] { series.write(1.0, "1", frame.particles, frame.vectors, frame.scalars); });
    report("binary zlib appended (ParticleVtkSeries)", dir / "particles_1.vtp", binary);

    // the same data set through VTK's ASCII mode, for comparison
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName((dir / "particles_1.vtp").c_str());
    reader->Update();
    vtkNew<vtkXMLPolyDataWriter> ascii;
    ascii->SetInputData(reader->GetOutput());
    ascii->SetDataModeToAscii();
    ascii->SetFileName((dir / "ascii.vtp").c_str());
    report("VTK ASCII of the same arrays", dir / "ascii.vtp", bestSeconds(repeat, [&] { ascii->Write(); }));
    return 0;
}
