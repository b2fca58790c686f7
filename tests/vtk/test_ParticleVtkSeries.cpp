// ParticleVtkSeries read back through VTK's own XML reader (what ParaView
// uses): every array with its type, its values against the sample's formulas,
// the binary compressed appended layout, and the .pvd collection.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>

#include "ParticleSample.hpp"
#include "ParticleVtkSeries.H"

namespace fs = std::filesystem;
using namespace spoutlab;

namespace
{

// a double stored as float: within half a unit in the last place of a float
void expectFloat(double expected, double actual, const std::string& what)
{
    const double ulp = std::numeric_limits<float>::epsilon();
    EXPECT_NEAR(actual, expected, 0.5 * ulp * std::abs(expected) + 1e-45) << what;
}

class ParticleVtkFiles : public ::testing::Test
{
protected:
    fs::path dir = fs::temp_directory_path() / ("particleVtk_" + std::to_string(::getpid()));

    void SetUp() override { fs::remove_all(dir); }
    void TearDown() override { fs::remove_all(dir); }

    void writeSample(const std::string& timeName) const
    {
        ParticleVtkSeries(dir.string(), "particles")
            .write(std::stod(timeName), timeName, sample::particles(), sample::vectors(), sample::scalars());
    }

    vtkSmartPointer<vtkPolyData> read(const std::string& file) const
    {
        vtkNew<vtkXMLPolyDataReader> reader;
        reader->SetFileName((dir / file).c_str());
        reader->Update();
        EXPECT_EQ(reader->GetErrorCode(), 0u) << file;
        return reader->GetOutput();
    }

    vtkDataArray* pointArray(vtkPolyData* poly, const char* name) const
    {
        vtkDataArray* a = poly->GetPointData()->GetArray(name);
        EXPECT_NE(a, nullptr) << "no point array " << name;
        return a;
    }
};

} // namespace

TEST_F(ParticleVtkFiles, GeometryIsExactInDouble)
{
    writeSample("0.5");
    auto poly = read("particles_0.5.vtp");
    ASSERT_EQ(poly->GetNumberOfPoints(), vtkIdType(sample::count));
    EXPECT_EQ(poly->GetPoints()->GetDataType(), VTK_DOUBLE);
    EXPECT_EQ(poly->GetNumberOfVerts(), vtkIdType(sample::count)); // ParaView draws them

    vtkDataArray* id = pointArray(poly, "id");
    vtkDataArray* radius = pointArray(poly, "radius");
    ASSERT_TRUE(id && radius);
    EXPECT_EQ(id->GetDataType(), VTK_TYPE_INT64);
    EXPECT_EQ(radius->GetDataType(), VTK_DOUBLE);
    for (std::size_t i = 0; i < sample::count; ++i)
    {
        const Particle p = sample::particle(i);
        const auto k = vtkIdType(i);
        double x[3];
        poly->GetPoint(k, x);
        EXPECT_EQ(x[0], p.x.x);
        EXPECT_EQ(x[1], p.x.y);
        EXPECT_EQ(x[2], p.x.z);
        EXPECT_EQ(id->GetTuple1(k), double(p.id));
        EXPECT_EQ(radius->GetTuple1(k), p.radius);
    }
}

TEST_F(ParticleVtkFiles, FieldsInSinglePrecision)
{
    writeSample("0.5");
    auto poly = read("particles_0.5.vtp");
    vtkDataArray* v = pointArray(poly, "velocity");
    vtkDataArray* f = pointArray(poly, "fluidForce");
    vtkDataArray* drag = pointArray(poly, "dragForce");
    vtkDataArray* T = pointArray(poly, "temperature");
    ASSERT_TRUE(v && f && drag && T);
    EXPECT_EQ(v->GetNumberOfComponents(), 3);
    EXPECT_EQ(T->GetNumberOfComponents(), 1);
    EXPECT_EQ(poly->GetPointData()->GetVectors(), v);
    EXPECT_EQ(std::string(poly->GetPointData()->GetScalars()->GetName()), "radius");
    for (std::size_t i = 0; i < sample::count; ++i)
    {
        const auto k = vtkIdType(i);
        const Vec3 vi = sample::particle(i).v, fi = sample::fluidForce(i);
        const double* a = v->GetTuple3(k);
        expectFloat(vi.x, a[0], "velocity x");
        expectFloat(vi.y, a[1], "velocity y");
        expectFloat(vi.z, a[2], "velocity z");
        const double* b = f->GetTuple3(k);
        expectFloat(fi.x, b[0], "fluidForce x");
        expectFloat(fi.y, b[1], "fluidForce y");
        expectFloat(fi.z, b[2], "fluidForce z");
        expectFloat(sample::temperature(i), T->GetTuple1(k), "temperature");
    }
    EXPECT_EQ(drag->GetMaxNorm(), 0.0);
    vtkDataArray* time = poly->GetFieldData()->GetArray("TimeValue");
    ASSERT_NE(time, nullptr);
    EXPECT_EQ(time->GetTuple1(0), 0.5);
}

TEST_F(ParticleVtkFiles, BinaryCompressedAppended)
{
    writeSample("0.5");
    std::ifstream in(dir / "particles_0.5.vtp", std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string head = text.substr(0, text.find("<AppendedData"));
    EXPECT_NE(head.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
    EXPECT_NE(head.find("header_type=\"UInt64\""), std::string::npos);
    EXPECT_EQ(head.find("format=\"ascii\""), std::string::npos);
    EXPECT_EQ(head.find("format=\"binary\""), std::string::npos);
    EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
    // raw, the sample would take 5000 x (3 x 8 + 8 + 8 + 3 x 3 x 4 + 4 + 2 x 8) bytes
    EXPECT_LT(text.size(), sample::count * 96);
}

// The collection lists each file on disk once, in time order, also when a
// restarted run writes a time again; no temporary files are left behind
TEST_F(ParticleVtkFiles, CollectionInTimeOrder)
{
    for (const char* t : {"0.2", "0.1", "0.15", "0.1"}) writeSample(t);
    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName((dir / "particles.pvd").c_str());
    ASSERT_EQ(parser->Parse(), 1);
    vtkXMLDataElement* root = parser->GetRootElement();
    ASSERT_EQ(std::string(root->GetAttribute("type")), "Collection");
    vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
    ASSERT_NE(collection, nullptr);
    ASSERT_EQ(collection->GetNumberOfNestedElements(), 3);
    const char* times[] = {"0.1", "0.15", "0.2"};
    for (int n = 0; n < 3; ++n)
    {
        vtkXMLDataElement* set = collection->GetNestedElement(n);
        EXPECT_EQ(std::stod(set->GetAttribute("timestep")), std::stod(times[n]));
        const std::string file = set->GetAttribute("file");
        EXPECT_EQ(file, "particles_" + std::string(times[n]) + ".vtp");
        EXPECT_EQ(read(file)->GetNumberOfPoints(), vtkIdType(sample::count));
    }
    for (const auto& entry : fs::directory_iterator(dir))
    {
        EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
    }
}
