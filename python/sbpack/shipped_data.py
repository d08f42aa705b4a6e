"""The packings of the repository's data/ that the module carries (docs/python.md, "Data"), so
that a script runs from any directory, in the CMake build and after ``pip install .`` alike; the
list is python/CMakeLists.txt's (sbpack_shipped_data), what the package's data/ folder holds."""
import os

_FOLDER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")


def data_files():
    """The names of the packings the module carries (data/README.md says what each is)."""
    return sorted(os.listdir(_FOLDER)) if os.path.isdir(_FOLDER) else []


def data_file(name):
    """The path of the packing `name` the module carries, e.g. ``data_file("mrj-p1.5-1000.h5")``;
    FileNotFoundError naming the ones it has otherwise."""
    if name not in data_files():
        raise FileNotFoundError(f"sbpack.data_file: no packing {name!r} ships with the module; "
                                f"it has {', '.join(data_files()) or 'none'}")
    return os.path.join(_FOLDER, name)
