"""sbpack: MRJ packings of superballs from Python (docs/python.md).

The C++ core (the libraries of sbgen and sbanalyze) is the extension ``sbpack._sbpack``; this
package adds the analyses as objects, a reader of results files and the figures (``sbpack.plot``).
"""
from ._sbpack import Packing, __version__, expected_collisions, generate
from .analyses import ANALYSES, analyze
from .analyses import (Contacts, Hyperuniformity, Order, PoreSizes,  # noqa: F401 (made from
                       SpectralDensity, StructureFactor, Transport,  # the registry)
                       Voxelization)
from .results import read_results

__all__ = ["Packing", "generate", "expected_collisions", "ANALYSES", "analyze", "read_results",
           "__version__"] + [cls.__name__ for cls in ANALYSES]
