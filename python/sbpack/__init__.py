"""sbpack: MRJ packings of superballs from Python (docs/python.md).

The C++ core (the libraries of sbgen and sbanalyze) is the extension ``sbpack._sbpack``; this
package adds the analyses as objects, a reader of results files and the figures (``sbpack.plot``).
"""
from ._sbpack import Packing, __version__, expected_collisions, generate
from .analyses import (Contacts, Hyperuniformity, Order, PoreSizes, SpectralDensity,
                       StructureFactor, Transport, analyze)
from .results import read_results

__all__ = ["Packing", "generate", "expected_collisions", "Contacts", "StructureFactor",
           "SpectralDensity", "PoreSizes", "Transport", "Hyperuniformity", "Order", "analyze",
           "read_results", "__version__"]
