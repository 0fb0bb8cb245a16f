#include "vtkGlobeTerrainClamp.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeTerrain.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/GeodesicLine.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

vtkStandardNewMacro(vtkGlobeTerrainClamp);
vtkCxxSetObjectMacro(vtkGlobeTerrainClamp, Terrain, vtkGlobeTerrain);
vtkCxxSetObjectMacro(vtkGlobeTerrainClamp, Ellipsoid, vtkGlobeEllipsoid);

vtkGlobeTerrainClamp::vtkGlobeTerrainClamp() = default;

vtkGlobeTerrainClamp::~vtkGlobeTerrainClamp()
{
  this->SetTerrain(nullptr);
  this->SetEllipsoid(nullptr);
}

vtkMTimeType vtkGlobeTerrainClamp::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->Terrain)
  {
    t = std::max(t, this->Terrain->GetMTime());
  }
  if (this->Ellipsoid)
  {
    t = std::max(t, this->Ellipsoid->GetMTime());
  }
  return t;
}

namespace
{
/// Points between two geodetic positions: equal parts of the edge along the geodesic.
struct Densifier
{
  vtkGlobeEllipsoid* Body;
  double MaximumLength;
  std::unique_ptr<GeographicLib::Geodesic> Geodesic; // biaxial bodies

  /// Writes the lon/lat of the n-1 inner points of the edge a -> b into `inner` (2 each).
  void Inner(const double a[2], const double b[2], std::vector<double>& inner)
  {
    inner.clear();
    if (!(this->MaximumLength > 0.0) || !std::isfinite(a[0] + a[1] + b[0] + b[1]))
    {
      return;
    }
    if (this->Geodesic)
    {
      double s12, azi1, azi2;
      this->Geodesic->Inverse(a[1], a[0], b[1], b[0], s12, azi1, azi2);
      const int n = static_cast<int>(std::ceil(s12 / this->MaximumLength));
      if (n <= 1)
      {
        return;
      }
      const GeographicLib::GeodesicLine line = this->Geodesic->Line(a[1], a[0], azi1);
      for (int k = 1; k < n; ++k)
      {
        double lat, lon;
        line.Position(s12 * k / n, lat, lon);
        inner.push_back(lon);
        inner.push_back(lat);
      }
      return;
    }
    // Triaxial: the chord, scaled to the surface.
    double pa[3], pb[3];
    const double la[3] = { a[0], a[1], 0.0 }, lb[3] = { b[0], b[1], 0.0 };
    this->Body->GeodeticToCartesian(la, pa);
    this->Body->GeodeticToCartesian(lb, pb);
    const double chord = std::sqrt(vtkMath::Distance2BetweenPoints(pa, pb));
    const int n = static_cast<int>(std::ceil(chord / this->MaximumLength));
    for (int k = 1; k < n; ++k)
    {
      const double t = static_cast<double>(k) / n;
      const double p[3] = { pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1]),
        pa[2] + t * (pb[2] - pa[2]) };
      double s[3], llh[3];
      if (this->Body->ScaleToGeodeticSurface(p, s) && this->Body->CartesianToGeodetic(s, llh))
      {
        inner.push_back(llh[0]);
        inner.push_back(llh[1]);
      }
    }
  }
};
} // namespace

int vtkGlobeTerrainClamp::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!this->Terrain || !this->Ellipsoid)
  {
    vtkErrorMacro(<< "No " << (this->Terrain ? "Ellipsoid" : "Terrain")
                  << ": set the globe's (vtkGlobeMapper::GetTerrain(), GetEllipsoid())");
    return 0;
  }
  if (!input || !input->GetPoints())
  {
    return 1; // nothing to clamp
  }
  this->Terrain->Update();
  Densifier densify{ this->Ellipsoid, this->MaximumSegmentLength, nullptr };
  if (this->Ellipsoid->IsBiaxial())
  {
    densify.Geodesic = std::make_unique<GeographicLib::Geodesic>(
      this->Ellipsoid->GetRadii()[0], this->Ellipsoid->GetFlattening());
  }

  vtkPoints* inPoints = input->GetPoints();
  const vtkIdType nIn = inPoints->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->Allocate(nIn);
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->InterpolateAllocate(inPD, nIn);

  auto place = [this, &points](double lon, double lat, double z) {
    double h = this->HeightOffset;
    if (this->HeightMode == RelativeToTerrain && std::isfinite(z))
    {
      h += z;
    }
    double llh[3] = { lon, lat, h };
    if (!std::isfinite(lon) || !std::isfinite(lat))
    {
      llh[0] = llh[1] = 0.0;
    }
    else
    {
      const double ground = this->Terrain->GetHeight(lon, lat);
      llh[2] += std::isfinite(ground) ? ground : 0.0;
    }
    double xyz[3];
    this->Ellipsoid->GeodeticToCartesian(llh, xyz);
    return points->InsertNextPoint(xyz);
  };
  for (vtkIdType i = 0; i < nIn; ++i)
  {
    double p[3];
    inPoints->GetPoint(i, p);
    place(p[0], p[1], p[2]);
    outPD->CopyData(inPD, i, i);
  }

  // Lines and polygons: each edge densified; the new points interpolate the edge's ends.
  std::vector<double> inner;
  auto densifyCells = [&](vtkCellArray* in, bool closed) {
    vtkNew<vtkCellArray> out;
    if (!in)
    {
      return vtkSmartPointer<vtkCellArray>(out.Get());
    }
    vtkNew<vtkIdList> ids;
    auto it = vtk::TakeSmartPointer(in->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* cell;
      it->GetCurrentCell(n, cell);
      ids->Reset();
      const vtkIdType edges = closed ? n : n - 1;
      for (vtkIdType k = 0; k < n; ++k)
      {
        ids->InsertNextId(cell[k]);
        if (k >= edges)
        {
          continue;
        }
        const vtkIdType a = cell[k], b = cell[(k + 1) % n];
        double pa[3], pb[3];
        inPoints->GetPoint(a, pa);
        inPoints->GetPoint(b, pb);
        densify.Inner(pa, pb, inner);
        const size_t m = inner.size() / 2;
        for (size_t j = 0; j < m; ++j)
        {
          const double t = static_cast<double>(j + 1) / (m + 1);
          const vtkIdType id = place(inner[2 * j], inner[2 * j + 1], pa[2] + t * (pb[2] - pa[2]));
          outPD->InterpolateEdge(inPD, id, a, b, t);
          ids->InsertNextId(id);
        }
      }
      out->InsertNextCell(ids);
    }
    return vtkSmartPointer<vtkCellArray>(out.Get());
  };
  output->SetPoints(points);
  output->SetVerts(input->GetVerts());
  output->SetLines(densifyCells(input->GetLines(), false));
  output->SetPolys(densifyCells(input->GetPolys(), true));
  output->SetStrips(input->GetStrips());
  output->GetCellData()->PassData(input->GetCellData());
  output->GetFieldData()->PassData(input->GetFieldData());
  return 1;
}

void vtkGlobeTerrainClamp::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Terrain: " << this->Terrain << "\n";
  os << indent << "Ellipsoid: " << this->Ellipsoid << "\n";
  os << indent << "HeightMode: " << (this->HeightMode == ClampToTerrain ? "ClampToTerrain" : "RelativeToTerrain")
     << "\n";
  os << indent << "HeightOffset: " << this->HeightOffset << "\n";
  os << indent << "MaximumSegmentLength: " << this->MaximumSegmentLength << "\n";
}
