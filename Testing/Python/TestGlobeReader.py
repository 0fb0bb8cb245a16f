"""vtkGlobeRasterReader and vtkGlobeLayer as a pipeline from Python: reader -> vtkImageShiftScale
-> layer through SetInputConnection.

Checks the wrapped reader's information pass and georeferencing field data, that the layer's
values follow the filter (raw + shift, row 0 north), that Modified() upstream re-loads the
layer, that a series of files is a time-varying source whose layer follows its UpdateTime
(loading again only for a new step), and that a reader error reaches a Python observer with the
file name and the reason.
"""
import os
import sys
import unittest

from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkImagingCore import vtkImageShiftScale

from vtkglobe import vtkGlobeLayer, vtkGlobeRasterReader

DATA = os.environ.get("VTKGLOBE_DATA_DIR",
                      os.path.join(os.path.dirname(__file__), "..", "..", "Data"))


class TestGlobeReader(unittest.TestCase):
    def test_reader_to_layer(self):
        reader = vtkGlobeRasterReader()
        reader.SetFileName(os.path.join(DATA, "earth", "relief_2deg.tif"))
        reader.UpdateInformation()
        info = reader.GetOutputInformation(0)
        self.assertEqual(info.Get(vtkStreamingDemandDrivenPipeline.WHOLE_EXTENT()),
                         (0, 179, 0, 89, 0, 0))
        self.assertEqual(info.Get(vtkDataObject.SPACING()), (2.0, 2.0, 1.0))
        # The origin is the centre of the south-west pixel.
        self.assertEqual(info.Get(vtkDataObject.ORIGIN()), (-179.0, -89.0, 0.0))

        shift = vtkImageShiftScale()
        shift.SetInputConnection(reader.GetOutputPort())
        shift.SetShift(1000.0)
        layer = vtkGlobeLayer()
        layer.SetInputConnection(shift.GetOutputPort())
        self.assertTrue(layer.Update())
        self.assertEqual(layer.GetEPSG(), 4326)
        self.assertEqual(layer.GetModelType(), vtkGlobeLayer.Geographic)
        self.assertTrue(layer.IsGlobal())

        fd = reader.GetOutput().GetFieldData()
        self.assertEqual(fd.GetArray(vtkGlobeRasterReader.GetEPSGArrayName()).GetValue(0), 4326)
        transform = fd.GetArray(vtkGlobeRasterReader.GetGeoTransformArrayName())
        self.assertEqual([transform.GetValue(i) for i in range(4)], [-180.0, 90.0, 2.0, 2.0])

        # Layer row 0 is north: layer post (row r, column c) = reader point (c, 89 - r).
        raw = reader.GetOutput().GetPointData().GetScalars()
        data = layer.GetData()
        for r, c in ((0, 0), (10, 37), (89, 179), (45, 90)):
            expected = raw.GetValue((89 - r) * 180 + c) + 1000.0
            self.assertAlmostEqual(data.GetValue(r * 180 + c), expected, delta=1e-3)

        loads = layer.GetNumberOfLoads()
        self.assertTrue(layer.Update())
        self.assertEqual(layer.GetNumberOfLoads(), loads)
        shift.SetShift(-1000.0)
        self.assertTrue(layer.Update())
        self.assertEqual(layer.GetNumberOfLoads(), loads + 1)
        self.assertAlmostEqual(data.GetValue(0) - 2000.0, layer.GetData().GetValue(0), delta=1e-3)
        reader.Modified()
        layer.Update()
        self.assertEqual(layer.GetNumberOfLoads(), loads + 2)

    def test_time_series(self):
        # Two steps of one file (the data does not matter here: the wrapped API does).
        relief = os.path.join(DATA, "earth", "relief_2deg.tif")
        reader = vtkGlobeRasterReader()
        reader.AddFileName(relief, 2026.5)
        reader.AddFileName(relief, 2026.0)
        self.assertEqual(reader.GetNumberOfFileNames(), 2)
        reader.UpdateInformation()
        info = reader.GetOutputInformation(0)
        self.assertEqual(info.Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS()), (2026.0, 2026.5))
        layer = vtkGlobeLayer()
        layer.SetInputConnection(reader.GetOutputPort())
        for time, step, loads in ((2026.2, 2026.0, 1), (2026.4, 2026.0, 1), (2027.0, 2026.5, 2)):
            layer.SetUpdateTime(time)
            self.assertTrue(layer.Update())
            self.assertEqual(layer.GetDataTime(), step)
            self.assertEqual(layer.GetNumberOfLoads(), loads)

    def test_errors_reach_python(self):
        reader = vtkGlobeRasterReader()
        missing = os.path.join(DATA, "earth", "no_such_file.tif")
        reader.SetFileName(missing)
        messages = []
        reader.AddObserver("ErrorEvent", lambda obj, event: messages.append(obj.GetLastError()))
        reader.GetExecutive().AddObserver("ErrorEvent", lambda obj, event: None)
        layer = vtkGlobeLayer()
        layer_messages = []
        layer.AddObserver("ErrorEvent", lambda obj, event: layer_messages.append(event))
        layer.SetInputConnection(reader.GetOutputPort())
        self.assertFalse(layer.Update())
        self.assertFalse(layer.IsValid())
        self.assertEqual(messages, ["the file does not exist"])
        self.assertEqual(len(layer_messages), 1)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
