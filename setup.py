"""pip's entry to the CMake build (pyproject.toml): builds the extension blockdem._core with
CMake, for the interpreter pip runs, and puts it beside the package's .py files."""
import os
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        # BLOCKDEM_CMAKE_BUILD_DIR=build reuses the folder `make build` configured (its options
        # kept); by default a folder of its own with only the module's targets.
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 2))
        reused = os.environ.get("BLOCKDEM_CMAKE_BUILD_DIR")
        build_dir = Path(reused) if reused else Path(self.build_temp) / "cmake"
        options = [f"-DPython_EXECUTABLE={sys.executable}", "-DBLOCKDEM_BUILD_PYTHON=ON"]
        if not reused:
            options += ["-DCMAKE_BUILD_TYPE=Release", "-DBLOCKDEM_BUILD_TESTS=OFF", "-DBLOCKDEM_BUILD_BENCHMARKS=OFF"]
        subprocess.run(["cmake", "-S", str(SOURCE_DIR), "-B", str(build_dir), *options], check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "blockdem_python", "-j", jobs], check=True)
        built = next((build_dir / "python" / "blockdem").glob("_core*.so"))
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        self.copy_file(str(built), str(target))


setup(ext_modules=[Extension("blockdem._core", sources=[])], cmdclass={"build_ext": CMakeBuild})
