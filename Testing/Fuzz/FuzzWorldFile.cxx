// Fuzz target: vtkGlobeRasterReader on an image with a world file and a .prj file. The input
// is split into the three files:
//   byte 0        bit 0: the image is .png (else .tif); bit 1: SetEPSG(4326);
//                 bit 2: no .prj file; bit 3: the world file is .wld (else .tfw / .pgw)
//   bytes 1-2     the world file's length (little-endian), bytes 3-4 the .prj's length
//   then          the world file's text, the .prj's text, and the image (the rest)
// Lengths beyond the input are cut to what is there.
#include "GlobeFuzz.h"

#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkGlobeRasterReader.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <algorithm>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  GlobeFuzz::Setup();
  if (size < 5)
  {
    return 0;
  }
  const uint8_t flags = data[0];
  size_t worldLength = data[1] | (data[2] << 8);
  size_t prjLength = data[3] | (data[4] << 8);
  data += 5;
  size -= 5;
  worldLength = std::min(worldLength, size);
  prjLength = std::min(prjLength, size - worldLength);
  const uint8_t* world = data;
  const uint8_t* prj = data + worldLength;
  const uint8_t* image = prj + prjLength;
  const size_t imageLength = size - worldLength - prjLength;

  const std::string& dir = GlobeFuzz::Directory("worldfile");
  const bool png = flags & 1;
  const std::string file = dir + (png ? "/input.png" : "/input.tif");
  const std::string worldFile =
    dir + ((flags & 8) ? "/input.wld" : png ? "/input.pgw" : "/input.tfw");
  if (!GlobeFuzz::WriteFile(file, image, imageLength) ||
    !GlobeFuzz::WriteFile(worldFile, world, worldLength) ||
    (!(flags & 4) && !GlobeFuzz::WriteFile(dir + "/input.prj", prj, prjLength)))
  {
    GlobeFuzz::Clear(dir);
    return 0;
  }
  {
    vtkNew<vtkGlobeRasterReader> reader;
    reader->SetFileName(file.c_str());
    reader->SetMaximumMemory(GlobeFuzz::MaximumMemoryMiB);
    if (flags & 2)
    {
      reader->SetEPSG(4326);
    }
    if (reader->GetExecutive()->UpdateInformation() && reader->GetExecutive()->Update())
    {
      vtkImageData* output = reader->GetOutput();
      double bounds[6];
      output->GetBounds(bounds);
      if (vtkDataArray* scalars = output->GetPointData()->GetScalars())
      {
        double range[2];
        scalars->GetRange(range, -1);
      }
    }
  }
  GlobeFuzz::Clear(dir);
  return 0;
}
