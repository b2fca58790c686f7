#pragma once
// ParaView output through VTK's own XML writers.  Every file is binary,
// zlib-compressed and appended (the arrays follow the XML header as raw
// compressed blocks), which ParaView and VTK read directly and which is
// several times smaller and faster to write than ASCII.
//
// These functions write exactly the file they are given: how it is put in
// place (a temporary renamed at once, or at the end of a procsim command) is
// the caller's policy.
#include <string>
#include <utility>
#include <vector>

#include <vtkSmartPointer.h>

class vtkDoubleArray;
class vtkFloatArray;
class vtkPolyData;
class vtkStructuredGrid;

namespace spoutlab::vtkxml
{

// `file` in the .vtp / .vts layout (whatever its name ends with); the
// directory must exist.  Throws std::runtime_error naming the file on failure.
void write(vtkPolyData* data, const std::string& file);
void write(vtkStructuredGrid* data, const std::string& file);

// A named array of n tuples.  Coordinates are kept in double; fields in
// single precision (7 significant digits, finer than anything the models
// resolve), which is what makes the compressed files small: the low
// mantissa bytes of a double are noise that zlib cannot shrink.
vtkSmartPointer<vtkDoubleArray> doubleArray(const std::string& name, int components, std::size_t n);
vtkSmartPointer<vtkFloatArray> floatArray(const std::string& name, int components, std::size_t n);

// The text of a .pvd collection: (time, file name relative to the .pvd),
// listed in the order given
using CollectionEntries = std::vector<std::pair<double, std::string>>;
std::string collection(const CollectionEntries& entries);

} // namespace spoutlab::vtkxml
