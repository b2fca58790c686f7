// writeParticleSample DIR: the sample frame (ParticleSample.hpp) at t = 0.5 s
// as DIR/particles_0.5.vtp and DIR/particles.pvd, and the same data as VTK
// writes it with its own defaults (32-bit headers, no compression):
// DIR/plain.vtp, the layout of a file saved from ParaView.
#include <iostream>
#include <string>

#include <vtkNew.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include "ParticleSample.hpp"
#include "ParticleVtkSeries.H"

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::cerr << "usage: writeParticleSample DIR\n";
        return 2;
    }
    const std::string dir = argv[1];
    namespace sample = spoutlab::sample;
    spoutlab::ParticleVtkSeries(dir, "particles")
        .write(0.5, "0.5", sample::particles(), sample::vectors(), sample::scalars());

    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName((dir + "/particles_0.5.vtp").c_str());
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputConnection(reader->GetOutputPort());
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressor(nullptr);
    writer->SetHeaderTypeToUInt32();
    writer->SetFileName((dir + "/plain.vtp").c_str());
    return writer->Write() == 1 ? 0 : 1;
}
