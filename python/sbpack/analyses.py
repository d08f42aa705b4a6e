"""The analyses of sbanalyze as objects (docs/python.md, "Analyses").

Each takes the command line's options as keywords (``qmax=20`` is ``--qmax 20``; a pair such as
``alpha_window=(1, 5.8)`` is ``--alpha-window 1,5.8``), checked by sbanalyze's own parser, so the
defaults and the messages (``ValueError``) are the command line's. ``compute(packing)`` runs the
same stages as ``sbanalyze --compute NAME`` on that packing and returns the object; the results
are attributes named as in the results file (docs/results-schema.md), e.g. ``StructureFactor().
compute(p).S``; ``groups`` holds every group the run filled, as dicts of numpy arrays and numbers;
``dir()`` (and so tab completion) lists the results' names once computed. The classes are made
from sbanalyze's registry of analyses (``_sbpack.analysis_registry()``; ``ANALYSES`` lists
them): a new analysis there is a new class here, with its options.

What sbanalyze prints as a warning is one RuntimeWarning per message, its continuation lines (the
gap distribution of unresolved contacts, ...) included, raised at the caller's line; stage lines
(``analyze(quiet=False)``) go to sys.stderr.
"""
from . import _sbpack


def _option(name, value):
    if isinstance(value, (tuple, list)):
        value = ",".join(str(v) for v in value)
    return ["--" + name.replace("_", "-"), str(value)]


class _Analysis:
    _compute = ""   # the --compute name
    _group = ""     # its results group
    _options = ()   # the keywords it takes (the command line's options, dashes as underscores)

    def __init__(self, **options):
        unknown = sorted(set(options) - set(self._options))
        if unknown:
            raise TypeError(f"{type(self).__name__}: unknown option(s) {', '.join(unknown)} "
                            f"(takes {', '.join(self._options)})")
        args = ["--compute", self._compute]
        for name, value in options.items():
            args += _option(name, value)
        self._analyzer = _sbpack.Analyzer(args)
        self.groups = None

    def compute(self, packing, input="<python>"):
        """Runs the analysis on ``packing`` (an sbpack.Packing); returns self. ``input`` is the
        name the results give the packing (``file['input']``). The GIL is released; Ctrl-C stops
        it at its next chunk (KeyboardInterrupt)."""
        self.groups = self._analyzer.compute(packing, input)
        return self

    @property
    def threads(self):
        return self._analyzer.threads

    def _result_names(self):
        """The names of the results, as attributes: its own group's, then the other groups' (the
        first group that has a name gives it); none before compute()."""
        groups = self.__dict__.get("groups") or {}
        names = {}
        for group in (self._group, *groups):
            names.update(dict.fromkeys(n for n in groups.get(group, {}) if n.isidentifier()))
        return list(names)

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._result_names()))

    def __getattr__(self, name):
        groups = self.__dict__.get("groups")
        if groups is None:
            raise AttributeError(f"{type(self).__name__}.{name}: call compute(packing) first")
        for group in (self._group, *groups):
            if group in groups and name in groups[group]:
                return groups[group][name]
        raise AttributeError(f"{type(self).__name__} has no result '{name}' "
                             f"(groups: {', '.join(groups)})")

    def __repr__(self):
        state = "computed" if self.groups is not None else "not computed"
        return f"<sbpack.{type(self).__name__} ({state})>"


def _keyword_doc(option, table):
    """One keyword of a class's docstring, from sbanalyze's option table."""
    row = table[option]
    default = f" (default {row['default']})" if row["default"] else ""
    return f"    {option.replace('-', '_')}: {row['value']}{default}, as --{option}"


def _analysis_class(row, table):
    """The class of one registry row (pipeline/analysis_registry.cpp): its --compute name, its
    own results group and its options (the command line's, dashes as underscores), documented
    from sbanalyze's option table (analysis/cli/option_table.cpp)."""
    description = row["description"][0].upper() + row["description"][1:]
    keywords = "\n".join(_keyword_doc(o, table) for o in ("threads", *row["options"]))
    doc = (f"{description} (--compute {row['name']}; results groups: "
           f"{', '.join(row['groups'])}).\n\nKeywords (sbanalyze --help says more):\n{keywords}")
    return type(row["python_class"], (_Analysis,), {
        "__doc__": doc,
        "__module__": __name__,
        "_compute": row["name"],
        "_group": row["groups"][0],
        "_options": ("threads",) + tuple(o.replace("-", "_") for o in row["options"]),
    })


# One class per analysis of sbanalyze's registry: Contacts, StructureFactor, SpectralDensity,
# Voxelization, PoreSizes, Transport, Hyperuniformity, Order, ...
ANALYSES = tuple(_analysis_class(row, _sbpack.analysis_options())
                 for row in _sbpack.analysis_registry())
globals().update({cls.__name__: cls for cls in ANALYSES})


def analyze(paths, out, compute="all", quiet=True, **options):
    """``sbanalyze PATHS... --out OUT --compute COMPUTE [options]`` in-process (the same run:
    every input checked first, ensembles of equal p and N, the results file written atomically);
    returns ``read_results(out)``. Options as the command line's (``threads=2``, ``voxels=100``,
    ``fft_plan="estimate"``, ...); warnings are RuntimeWarnings, stage lines go to sys.stderr
    unless ``quiet``."""
    from .results import read_results
    args = [str(p) for p in ([paths] if isinstance(paths, (str, bytes)) else paths)]
    args += ["--out", str(out), "--compute", compute] + (["--quiet"] if quiet else [])
    for name, value in options.items():
        args += _option(name, value)
    _sbpack.analyze(args)
    return read_results(out)
