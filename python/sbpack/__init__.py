"""sbpack: MRJ packings of superballs from Python (docs/python.md).

The C++ core (the libraries of sbgen and sbanalyze) is the extension ``sbpack._sbpack``; this
package adds the analyses as objects, a reader of results files and the figures (``sbpack.plot``).
"""
from ._arguments import expected_collisions, generate, name_argument_errors
from ._sbpack import Packing, __version__, shape_families
from .analyses import analyze
from .analysis_base import Analysis, Result
from .analysis_classes import *  # noqa: F401,F403 (Contacts, ContactsResult, ...: __all__)
from .analysis_classes import __all__ as _analysis_names
from .results import read_results
from .shipped_data import data_file, data_files

name_argument_errors()

__all__ = ["Packing", "generate", "expected_collisions", "shape_families", "analyze", "read_results", "data_file",
           "data_files", "Analysis",
           "Result", "__version__", *_analysis_names]
