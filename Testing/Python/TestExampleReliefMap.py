"""Examples/Python/relief_map.py: a DEM alone, coloured by a hypsometric tint and hill-shaded.

- --help exits 0 and names the bodies and colour maps; a bad --opacity exits 2.
- Run as a user runs it (headless, --out): it writes the picture.
- Built in-process (its build()), each place below, projected into the window, shows its
  height's colour class in the Earth map: the Bay of Bengal (about -2,500 m in the 2-degree
  relief) blue, the Ganges plain (about 100 m) green, the Tibetan plateau (about 4,500 m)
  brown-grey; with --opacity 0 none of them is coloured (the body's base colour, shaded).
- The Moon's and Mars's maps span their bodies' relief: each covers its known lowest and highest
  points (Moon -9.1 .. +10.8 km, Mars -8.2 .. +21.2 km) and grows monotonically in height.
"""
import os
import sys
import unittest

from globe_test_support import EXAMPLES, ExampleTest, Image, project, run_example

sys.path.insert(0, EXAMPLES)
import relief_map as rm  # noqa: E402

SIZE = (400, 300)
PLACES = {  # (lon, lat): the colour class its height has in the Earth map
    "Bay of Bengal": ((89.0, 15.0), "blue"),
    "Ganges plain": ((81.0, 26.5), "green"),
    "Tibetan plateau": ((88.0, 33.0), "highland"),
}


def colour_class(rgb):
    r, g, b = rgb
    if b > r + 20 and b >= g:
        return "blue"
    if g > r + 10 and g > b + 10:
        return "green"
    if r >= g and r >= b:
        return "highland"  # ochre, brown, grey, white: red leads
    return "other"


class TestExampleReliefMap(ExampleTest):
    def test_help_and_bad_input(self):
        self.check_help("relief_map.py", ("--dem", "--body", "--colors", "mars", "moon"))
        code, _, stderr = run_example("relief_map.py", "--opacity", "2", "--out", self.out)
        self.assertEqual(code, 2)
        self.assertIn("--opacity", stderr)

    def test_runs(self):
        code, stdout, _ = run_example("relief_map.py", "--out", self.out, "--size", "320x240",
                                      "--grid", "128")
        self.assertEqual(code, 0)
        self.assertIn("wrote", stdout)
        self.assertEqual((Image(self.out).width, Image(self.out).height), (320, 240))

    def classes(self, opacity):
        window, renderer, mapper = rm.build(rm.globe_scene.DATA, SIZE, 256, opacity=opacity)
        window.Render()
        window.Render()
        path = os.path.join(self.tmp.name, "relief-%g.png" % opacity)
        rm.globe_scene.show(window, path, False)
        image = Image(path)
        body = mapper.GetEllipsoid()
        found = {}
        for name, ((lon, lat), _) in PLACES.items():
            p = body.GeodeticToCartesian(lon, lat, 0.0)
            x, y = project(renderer, p)
            self.assertTrue(0 <= x < SIZE[0] and 0 <= y < SIZE[1], name + " is in view")
            found[name] = (image(int(x), int(y)), colour_class(image(int(x), int(y))))
            print("opacity %g: %-16s at (%3.0f, %3.0f): rgb %s, %s"
                  % (opacity, name, x, y, found[name][0], found[name][1]))
        return found

    def test_places_show_their_heights(self):
        tinted = self.classes(1.0)
        for name, (_, expected) in PLACES.items():
            self.assertEqual(tinted[name][1], expected, name)
        plain = self.classes(0.0)
        self.assertEqual(len({c for _, c in plain.values()}), 1,
                         "without the tint the three places share the base colour's class")

    def test_moon_and_mars_maps(self):
        for body, (low, high) in (("moon", (-9100, 10800)), ("mars", (-8200, 21200))):
            points = rm.COLOR_MAPS[body]
            heights = [p[0] for p in points]
            self.assertEqual(heights, sorted(heights), body)
            self.assertLessEqual(heights[0], low, body)
            self.assertGreaterEqual(heights[-1], high, body)
            tint = rm.height_colors(body)
            self.assertEqual(tuple(tint.GetRange()), (heights[0], heights[-1]))


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
