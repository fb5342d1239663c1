"""The build backend of `pip install .` (PEP 517, named in pyproject.toml):
builds the module afford._afford with CMake (the project's own build, only
the target afford_python) and packs it with the package's Python files into
a wheel. It needs nothing from a package index, so that pip's isolated build
works offline: only CMake, Ninja and the Debian packages of
scripts/install.sh. Set AFFORD_BUILD_DIR to keep the CMake build between
runs (default: a temporary folder)."""

import base64
import hashlib
import io
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tarfile
import tempfile
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PACKAGE_FILES = ("__init__.py", "__init__.pyi", "py.typed")


def _version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        found = re.search(r"project\(afford VERSION ([0-9.]+)", f.read())
    if not found:
        raise RuntimeError("CMakeLists.txt: no 'project(afford VERSION x.y.z)' to take the version from")
    return found.group(1)


def _metadata():
    return (f"Metadata-Version: 2.1\nName: afford\nVersion: {_version()}\n"
            "Summary: Infer what an articulated hand tool is for by simulating it\n"
            "Requires-Python: >=3.9\nRequires-Dist: numpy\n")


def _tag():
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{python}-{python}-{platform}"


def _build_module(build_dir):
    """Configures and builds afford_python; returns the folder holding the module."""
    subprocess.run(["cmake", "-S", ROOT, "-B", build_dir, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                    "-DAFFORD_TESTS=OFF", "-DAFFORD_BENCH=OFF", f"-DPython_EXECUTABLE={sys.executable}"],
                   check=True, stdout=sys.stderr)
    subprocess.run(["cmake", "--build", build_dir, "--target", "afford_python"], check=True, stdout=sys.stderr)
    return os.path.join(build_dir, "python", "afford")


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def _wheel_file():
    return f"Wheel-Version: 1.0\nGenerator: afford_build\nRoot-Is-Purelib: false\nTag: {_tag()}\n"


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    """The metadata without building (pip asks for it first)."""
    info = f"afford-{_version()}.dist-info"
    os.makedirs(os.path.join(metadata_directory, info), exist_ok=True)
    for name, text in (("METADATA", _metadata()), ("WHEEL", _wheel_file())):
        with open(os.path.join(metadata_directory, info, name), "w") as f:
            f.write(text)
    return info


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    version, tag = _version(), _tag()
    build_dir = os.environ.get("AFFORD_BUILD_DIR") or tempfile.mkdtemp(prefix="afford-wheel-")
    try:
        module_dir = _build_module(build_dir)
        modules = [f for f in os.listdir(module_dir) if f.startswith("_afford") and f.endswith(".so")]
        if len(modules) != 1:
            raise RuntimeError(f"{module_dir}: expected one _afford*.so, found {modules}")
        files = [(f"afford/{f}", os.path.join(ROOT, "python", "afford", f)) for f in PACKAGE_FILES]
        files.append((f"afford/{modules[0]}", os.path.join(module_dir, modules[0])))
        info = f"afford-{version}.dist-info"
        wheel_name = f"afford-{version}-{tag}.whl"
        records = []
        with zipfile.ZipFile(os.path.join(wheel_directory, wheel_name), "w", zipfile.ZIP_DEFLATED) as wheel:
            def add(name, data):
                wheel.writestr(name, data)
                records.append(_record_line(name, data))

            for name, path in files:
                with open(path, "rb") as f:
                    add(name, f.read())
            add(f"{info}/METADATA", _metadata().encode())
            add(f"{info}/WHEEL", _wheel_file().encode())
            wheel.writestr(f"{info}/RECORD", "\n".join(records + [f"{info}/RECORD,,"]) + "\n")
        return wheel_name
    finally:
        if not os.environ.get("AFFORD_BUILD_DIR"):
            shutil.rmtree(build_dir, ignore_errors=True)


def build_sdist(sdist_directory, config_settings=None):
    """The source tree, less builds, outputs and version control."""
    name = f"afford-{_version()}"
    skipped = re.compile(r"^(build[^/]*|out|\.git)(/|$)")

    def keep(info):
        relative = info.name[len(name) + 1:]
        return None if skipped.match(relative) or "__pycache__" in relative else info

    path = os.path.join(sdist_directory, f"{name}.tar.gz")
    with tarfile.open(path, "w:gz") as tar:
        tar.add(ROOT, arcname=name, filter=keep)
        info = tarfile.TarInfo(f"{name}/PKG-INFO")
        data = _metadata().encode()
        info.size = len(data)
        tar.addfile(info, io.BytesIO(data))
    return os.path.basename(path)
