#include "VtkXmlFile.hpp"

#include <sstream>
#include <stdexcept>

#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLStructuredGridWriter.h>

namespace spoutlab::vtkxml
{

namespace
{

// The one writer setting of the project: binary appended, raw (not base64),
// zlib blocks, 64-bit block headers so no array is limited to 4 GB.
void writeAppended(vtkXMLWriter& writer, const std::string& file)
{
    writer.SetDataModeToAppended();
    writer.EncodeAppendedDataOff();
    writer.SetCompressorTypeToZLib();
    writer.SetHeaderTypeToUInt64();
    writer.SetByteOrderToLittleEndian();
    writer.SetFileName(file.c_str());
    if (writer.Write() != 1) throw std::runtime_error(file + ": VTK could not write the file");
}

template <class Array>
vtkSmartPointer<Array> namedArray(const std::string& name, int components, std::size_t n)
{
    auto a = vtkSmartPointer<Array>::New();
    a->SetName(name.c_str());
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(static_cast<vtkIdType>(n));
    return a;
}

} // namespace

void write(vtkPolyData* data, const std::string& file)
{
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(data);
    writeAppended(*writer, file);
}

void write(vtkStructuredGrid* data, const std::string& file)
{
    vtkNew<vtkXMLStructuredGridWriter> writer;
    writer->SetInputData(data);
    writeAppended(*writer, file);
}

vtkSmartPointer<vtkDoubleArray> doubleArray(const std::string& name, int components, std::size_t n)
{
    return namedArray<vtkDoubleArray>(name, components, n);
}

vtkSmartPointer<vtkFloatArray> floatArray(const std::string& name, int components, std::size_t n)
{
    return namedArray<vtkFloatArray>(name, components, n);
}

// VTK's own modules carry no .pvd writer (it lives in ParaView), and the
// format is a short list of <DataSet> elements.
std::string collection(const CollectionEntries& entries)
{
    std::ostringstream os;
    os.precision(12);
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
       << "  <Collection>\n";
    for (const auto& [time, file] : entries)
    {
        os << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\"0\" file=\"" << file << "\"/>\n";
    }
    os << "  </Collection>\n</VTKFile>\n";
    return os.str();
}

} // namespace spoutlab::vtkxml
