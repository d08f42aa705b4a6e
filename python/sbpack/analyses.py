"""A whole sbanalyze run in-process (docs/python.md, "Analyses"); the analyses one packing at a
time are the classes of sbpack.analysis_classes."""
from . import _sbpack
from ._arguments import check_keywords
from .analysis_base import command_line_option


def analyze(paths, out, compute="all", quiet=True, **options):
    """``sbanalyze PATHS... --out OUT --compute COMPUTE [options]`` in-process (the same run:
    every input checked first, ensembles of equal p and N, the results file written atomically);
    returns ``read_results(out)``. Options as the command line's (``threads=2``, ``voxels=100``,
    ``fft_plan="estimate"``, ...); warnings are RuntimeWarnings, stage lines go to sys.stderr
    unless ``quiet``."""
    from .results import read_results
    if isinstance(paths, _sbpack.Packing) or (
            isinstance(paths, (list, tuple)) and any(isinstance(p, _sbpack.Packing) for p in paths)):
        raise TypeError("analyze() takes packing files; a Packing goes to an analysis's "
                        "compute(packing), e.g. sbpack.Contacts().compute(packing)")
    check_keywords("analyze", options, [o.replace("-", "_") for o in _sbpack.analysis_options()])
    args = [str(p) for p in ([paths] if isinstance(paths, (str, bytes)) else paths)]
    args += ["--out", str(out), "--compute", compute] + (["--quiet"] if quiet else [])
    for name, value in options.items():
        args += command_line_option(name, value)
    _sbpack.analyze(args)
    return read_results(out)
