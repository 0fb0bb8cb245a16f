"""Every snippet of Documentation/user-guide.md runs.

- Each ```python block runs on its own with Debian's /usr/bin/python3, in a scratch folder whose
  Data/ is the source tree's (the guide's snippets run "from the source tree"). It must exit 0
  without any VTK error or warning on its output, and every PNG it writes must be a real
  picture (not one flat colour).
- Every ```cpp block must be a full program (a fragment could not be checked). Each is built
  with the guide's ```cmake project against VTKGlobe installed into a scratch prefix (as a user
  would: cmake --install, then find_package), run in the scratch folder, and checked like the
  Python blocks.
- ```sh blocks are for the reader to type; the scripts, examples and globe.sh sub-commands they
  name must exist.
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

from globe_test_support import DATA, SOURCE, Image

GUIDE = os.path.join(SOURCE, "Documentation", "user-guide.md")
BUILD = os.environ.get("VTKGLOBE_BUILD_DIR", os.path.join(SOURCE, "build"))
# Printed by the Rendering module on every window (a quad helper's unused attribute); harmless.
KNOWN_NOISE = ("texCoordIn",)


def blocks(language):
    with open(GUIDE) as f:
        text = f.read()
    return [(text.count("\n", 0, m.start()) + 2, m.group(1))
            for m in re.finditer(r"^```%s[^\n]*\n(.*?)^```" % language, text, re.S | re.M)]


def problems(output):
    """VTK's errors and warnings in a run's output, less the known noise."""
    return [line for line in output.splitlines()
            if re.search(r"\bERR\||\bWARN\||ERROR:|Warning:|Traceback", line)
            and not any(noise in line for noise in KNOWN_NOISE)]


class TestUserGuideSnippets(unittest.TestCase):
    def scratch(self):
        tmp = tempfile.mkdtemp(prefix="guide-")
        self.addCleanup(shutil.rmtree, tmp)
        os.symlink(DATA, os.path.join(tmp, "Data"))
        return tmp

    def check_pictures(self, folder, where):
        pictures = glob.glob(os.path.join(folder, "*.png"))
        for path in pictures:
            image = Image(path)
            colours = {p for _, _, p in image.pixels()}
            print("  %s: %dx%d, %d colours" % (os.path.basename(path), image.width,
                                                image.height, len(colours)))
            self.assertGreater(len(colours), 50, "%s: %s is flat" % (where, path))
        return pictures

    def test_python_blocks(self):
        snippets = blocks("python")
        self.assertGreaterEqual(len(snippets), 8)
        pictures = 0
        for line, code in snippets:
            with self.subTest(line=line):
                tmp = self.scratch()
                result = subprocess.run([sys.executable, "-c", code], cwd=tmp,
                                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                        universal_newlines=True, timeout=300)
                print("user-guide.md:%d -> exit %d\n%s" % (line, result.returncode,
                                                           result.stdout.strip()))
                self.assertEqual(result.returncode, 0, "user-guide.md:%d failed" % line)
                self.assertEqual(problems(result.stdout), [], "user-guide.md:%d" % line)
                pictures += len(self.check_pictures(tmp, "user-guide.md:%d" % line))
        self.assertGreaterEqual(pictures, 1)

    def test_cpp_programs(self):
        programs = blocks("cpp")
        projects = [code for _, code in blocks("cmake") if "project(" in code]
        self.assertGreaterEqual(len(programs), 1)
        self.assertEqual(len(projects), 1, "one CMake project to build the C++ programs with")
        for line, code in programs:
            self.assertIn("int main(", code, "user-guide.md:%d is not a full program" % line)
        cmake = projects[0]
        target, source = re.search(r"add_executable\((\w+)\s+([\w.]+)\)", cmake).groups()

        work = tempfile.mkdtemp(prefix="guide-cxx-")
        self.addCleanup(shutil.rmtree, work)
        prefix = os.path.join(work, "prefix")

        def run(*command, cwd=None):
            result = subprocess.run(list(command), cwd=cwd, stdout=subprocess.PIPE,
                                    stderr=subprocess.STDOUT, universal_newlines=True, timeout=600)
            if result.returncode != 0:
                print(result.stdout[-4000:])
            self.assertEqual(result.returncode, 0, " ".join(command))
            return result.stdout

        run("cmake", "--install", BUILD, "--prefix", prefix)
        for k, (line, code) in enumerate(programs):
            with self.subTest(line=line):
                project = os.path.join(work, "program%d" % k)
                os.makedirs(project)
                with open(os.path.join(project, "CMakeLists.txt"), "w") as f:
                    f.write(cmake)
                with open(os.path.join(project, source), "w") as f:
                    f.write(code)
                build = os.path.join(project, "build")
                run("cmake", "-S", project, "-B", build, "-DCMAKE_PREFIX_PATH=" + prefix,
                    "-DCMAKE_BUILD_TYPE=Release")
                run("cmake", "--build", build)
                tmp = self.scratch()
                result = subprocess.run([os.path.join(build, target)], cwd=tmp,
                                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                        universal_newlines=True, timeout=300)
                print("user-guide.md:%d (C++) -> exit %d\n%s" % (line, result.returncode,
                                                                 result.stdout.strip()))
                self.assertEqual(result.returncode, 0)
                self.assertEqual(problems(result.stdout), [])
                self.assertGreaterEqual(len(self.check_pictures(tmp, "user-guide.md:%d" % line)), 1)

    def test_shell_blocks_name_what_exists(self):
        with open(os.path.join(SOURCE, "Utilities", "globe.sh")) as f:
            script = f.read()
        subcommands = set(re.findall(r"^  (\w+)\)$", script, re.M))
        for line, code in blocks("sh"):
            for command in code.splitlines():
                for sub in re.findall(r"Utilities/globe\.sh (\w+)", command):
                    self.assertIn(sub, subcommands, "user-guide.md:%d: globe.sh %s" % (line, sub))
                # Whole paths only (not Testing/... inside Plugins/ParaView/Testing/...).
                paths = r"(?<![\w/.])((?:Examples|Utilities|Testing|Plugins)/[\w/.]+)"
                for path in re.findall(paths, command):
                    self.assertTrue(os.path.exists(os.path.join(SOURCE, path)),
                                    "user-guide.md:%d: %s does not exist" % (line, path))


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
