"""Python's own argument errors for the extension's entry points (issue 66 item 6): pybind11
answers a missing or unknown keyword with its signature list and the reprs of every argument
(whole arrays); these wrappers raise Python's TypeError, which names the argument, and suggest
the nearest keywords by sbpack's own rule for mistyped options (common/cli/option_suggestion)."""
import inspect

from . import _sbpack

_PACKING_INIT = _sbpack.Packing.__init__
_GENERATE = _sbpack.generate


def __init__(self, positions, orientations, box_length, *, semi_axis, semi_axes=None,
             source="arrays", shape=None, **parameters):
    # the shape's parameters by name (p=1.5 for superballs); an unknown family: the extension's
    # ValueError
    if shape is None or shape in _sbpack.shape_families():
        check_keywords("Packing.__init__", parameters, _shape_keywords(shape))
    _PACKING_INIT(self, positions, orientations, box_length, semi_axis=semi_axis,
                  semi_axes=semi_axes, source=source, shape=shape, parameters=parameters)


# The extension's own description (python/src/packing.cpp), without pybind11's signature line.
__init__.__doc__ = _PACKING_INIT.__doc__.split("\n\n", 1)[-1]


def _named(function, qualname):
    """`function` whose messages call it `qualname` (Python >= 3.11 names the code's qualname)."""
    function.__qualname__ = qualname
    if hasattr(function.__code__, "co_qualname"):
        function.__code__ = function.__code__.replace(co_qualname=qualname)
    return function


def _keywords(function):
    """The keyword names of an extension function, from its pybind11 signature line."""
    line = function.__doc__.splitlines()[0]
    inner = line[line.index("(") + 1:line.rindex(") ->")]
    return [part.split(":")[0].strip() for part in inner.split(",") if ":" in part]


def check_keywords(function, given, known):
    """Raises Python's TypeError for the first keyword of `given` not in `known`, with the
    nearest known ones by sbgen's rule for mistyped options ("did you mean gamma_slow?")."""
    for name in given:
        if name not in known:
            near = _sbpack.closest_options("--" + name, ["--" + k for k in known])
            hint = f"; did you mean {' or '.join(n[2:] for n in near)}?" if near else ""
            raise TypeError(f"{function}() got an unexpected keyword argument {name!r}{hint}")


def _shape_keywords(shape):
    """The parameters' names of the known family `shape` (None: the superball): the extension
    takes them as one dict, so that a new family adds no keyword here."""
    families = _sbpack.shape_families()
    return families[shape if shape is not None else next(iter(families))]


def _by_shape(function, name):
    """`function` of the extension with the shape's parameters by name (p=1.5; shape=NAME for
    another family) and its other keywords checked by check_keywords."""
    known = [k for k in _keywords(function) if k != "parameters"]

    def wrapped(*, shape=None, **options):
        if shape is not None and not isinstance(shape, str):
            raise TypeError(f"{name}() shape must be a str or None, not {type(shape).__name__}")
        if shape is not None and shape not in _sbpack.shape_families():
            return function(shape=shape)  # the extension's ValueError names the families
        names = _shape_keywords(shape)
        check_keywords(name, options, known + list(names))
        parameters = {k: options.pop(k) for k in names if k in options}
        return function(shape=shape, parameters=parameters, **options)
    wrapped.__name__ = name
    # pybind11's signature line, with the shape's keywords as they are given
    wrapped.__doc__ = function.__doc__.replace("parameters: dict = {}", "**shape_parameters")
    return _named(wrapped, name)


generate = _by_shape(_GENERATE, "generate")
expected_collisions = _by_shape(_sbpack.expected_collisions, "expected_collisions")


def name_argument_errors():
    """Installs the wrappers: Packing's constructor and sbpack.generate."""
    _sbpack.Packing.__init__ = _named(__init__, "Packing.__init__")
    _sbpack.Packing.__init__.__signature__ = inspect.signature(__init__)
