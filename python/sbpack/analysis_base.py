"""The base classes of sbpack's analyses (docs/python.md, "Analyses"); the classes themselves,
one per analysis of sbanalyze's registry, are written out at build time into
sbpack.analysis_classes (python/generate_analysis_classes.py).

An analysis's keywords are the command line's options (``qmax=20`` is ``--qmax 20``; a pair such
as ``alpha_window=(1, 5.8)`` is ``--alpha-window 1,5.8``), checked by sbanalyze's own parser, so
the defaults and the messages (``ValueError``) are the command line's. ``compute(packing)`` runs
the same stages as ``sbanalyze --compute NAME`` on that packing and returns its result object.

What sbanalyze prints as a warning is one RuntimeWarning per message, its continuation lines (the
gap distribution of unresolved contacts, ...) included, raised at the caller's line.
"""
from . import _sbpack


def command_line_option(name, value):
    """``--name value`` of one keyword (underscores to dashes; a sequence joined by commas). A
    sequence is taken only by the options whose value is a pair (``T1,T2``: two items) or a list
    (``LIST``); for any other it is refused, where ``tolerance=[1]`` was read as 1."""
    option = name.replace("_", "-")
    if isinstance(value, (tuple, list)):
        value_name = _sbpack.analysis_options().get(option, {}).get("value", "")
        pair, listed = "," in value_name, value_name == "LIST"
        if not ((listed and len(value) > 0) or (pair and len(value) == 2)):
            takes = "a pair" if pair else "a non-empty list" if listed else "one value"
            raise ValueError(f"{name}: a sequence of {len(value)} values; it takes {takes}")
        value = ",".join(str(v) for v in value)
    return ["--" + option, str(value)]


class Result:
    """The results of one compute(): ``groups``, every results group the run filled (dicts of
    numpy arrays and numbers, named as in docs/results-schema.md), and a property per field."""

    __slots__ = ("groups",)

    def __init__(self, groups):
        self.groups = groups

    def _field(self, group, name):
        return self.groups.get(group, {}).get(name)

    def __repr__(self):
        return f"<sbpack.{type(self).__name__} of groups {', '.join(self.groups)}>"


class Analysis:
    """One analysis of sbanalyze, set up once and computed on any number of packings."""

    _compute = ""  # the --compute name; each class's compute() returns its result class

    def __init__(self, **options):
        args = ["--compute", self._compute]
        for name, value in options.items():
            if value is not None:
                args += command_line_option(name, value)
        self._analyzer = _sbpack.Analyzer(args)

    @property
    def threads(self):
        """The threads the analysis runs on (``threads``, else the hardware's)."""
        return self._analyzer.threads

    def __repr__(self):
        return f"<sbpack.{type(self).__name__} (--compute {self._compute})>"
