"""Writes sbpack/analysis_classes.py, the analysis classes of sbanalyze's registry written out as a
real module (docs/python.md, "Analyses"), at build time (python/CMakeLists.txt):

    python3 python/generate_analysis_classes.py build/python/sbpack/_sbpack.*.so OUT.py

Everything comes from the one declaration of each thing in the built extension: the registry's
rows (_sbpack.analysis_registry(): name, class, description, groups, options), the option table
(_sbpack.analysis_options(): value name, default, help) and the results schema
(_sbpack.schema_json(): each group's fields with type, units and description). A class per
analysis takes its options as keyword-only parameters with their defaults, and compute() returns
a result class per analysis whose fields are properties, so that help(), dir(), an IDE and pdoc
see them before any run.
"""
import importlib.util
import json
import re
import sys
import textwrap

# Python's types of the schema's (docs/results-schema.md, "Types").
_TYPES = {"float64": "float", "int64": "int", "string": "str"}


def _python_default(row):
    """The default as a Python literal: None where it depends on another option or on the
    machine (threads), a tuple for a pair, else the number or the word the command line
    prints."""
    text = row["default"]
    if row["dependent_default"] or text == "":
        return None
    if "," in text:
        return tuple(_number(t) for t in text.split(","))
    return _number(text)


def _number(text):
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def _help_text(help_text):
    """The option's help as one paragraph (the command line wraps it at its own columns), without
    this machine's thread count."""
    return re.sub(r"the hardware's, \d+", "the hardware's", " ".join(help_text.split()))


def _parameter_doc(name, row):
    default = "the hardware's threads" if name == "threads" else repr(_python_default(row))
    lines = [f"{name.replace('-', '_')} : {row['value']}, default {default}"]
    body = f"{_help_text(row['help'])} (--{name})"
    lines += textwrap.wrap(body, 88, initial_indent="    ", subsequent_indent="    ",
                           break_on_hyphens=False)
    return lines


def _field_property(group, field):
    kind = "numpy.ndarray" if field["kind"] == "dataset" else _TYPES.get(field["type"], "object")
    doc = f"{field['description']} [{field['units']}] ({group}/{field['name']})"
    doc = "\n".join(textwrap.wrap(doc.replace('"', "'").replace("\\", "\\\\"), 88,
                                   break_on_hyphens=False))
    return (f"    @property\n"
            f"    def {field['name']}(self) -> \"{kind} | None\":\n"
            f"        \"\"\"{textwrap.indent(doc, '        ').lstrip()}\n"
            f"        (None where the run did not write it.)\"\"\"\n"
            f"        return self._field({group!r}, {field['name']!r})\n")


def _group_property(group, title):
    doc = f"The group {group}, {title}, as a dict of its fields (docs/results-schema.md)"
    doc = "\n".join(textwrap.wrap(doc.replace('"', "'"), 88, break_on_hyphens=False))
    return (f"    @property\n"
            f"    def {group}(self) -> \"dict | None\":\n"
            f"        \"\"\"{textwrap.indent(doc, '        ').lstrip()}\n"
            f"        (None where the run did not write it.)\"\"\"\n"
            f"        return self.groups.get({group!r})\n")


def _shared_tables(row, schema):
    """The row's own groups that share their fields with another of them (jamming_local,
    jamming_collective, jamming_strict): each is one property, a dict, since their names
    coincide."""
    names = {g: [f["name"] for f in schema.get(g, [])] for g in row["groups"]}
    return {g for g in names if [h for h in names if names[h] == names[g]] != [g]}


def _result_class(row, schema, titles):
    """The result class: a property per field of its groups, its own groups first, each name
    once (the first group that has it gives it); groups that share one table a property each."""
    name = row["python_class"] + "Result"
    seen, properties = set(), []
    shared = _shared_tables(row, schema)
    for group in [*row["groups"], *row["need_groups"], "file"]:
        if group in shared:
            properties.append(_group_property(group, titles[group]))
            continue
        for field in schema.get(group, []):
            if field["name"].isidentifier() and field["name"] not in seen:
                seen.add(field["name"])
                properties.append(_field_property(group, field))
    doc = (f"What {row['python_class']}.compute returns: the fields of results group(s) "
           f"{', '.join(row['groups'])} (docs/results-schema.md) as properties; ``groups`` holds "
           f"every group the run filled as dicts.")
    return (f"class {name}(Result):\n"
            f"    {_docstring(doc, 4)}\n\n"
            f"    __slots__ = ()\n\n" + "\n".join(properties))


def _docstring(text, indent):
    lines = textwrap.wrap(text, 96 - indent, break_on_hyphens=False)
    return '"""' + ("\n" + " " * indent).join(lines) + '"""'


def _analysis_class(row, options):
    names = ["threads", *row["options"]]
    parameters = ", ".join(f"{n.replace('-', '_')}={_python_default(options[n])!r}"
                           if n != "threads" else "threads=None" for n in names)
    arguments = ", ".join(f"{n.replace('-', '_')}={n.replace('-', '_')}" for n in names)
    description = row["description"][0].upper() + row["description"][1:]
    doc = [*textwrap.wrap(f"{description} (sbanalyze --compute {row['name']}).", 92,
                          break_on_hyphens=False), "", "Parameters", "----------"]
    for n in names:
        doc += _parameter_doc(n, options[n])
    doc = "\n    ".join(doc)
    result = row["python_class"] + "Result"
    return (f"class {row['python_class']}(Analysis):\n"
            f"    \"\"\"{doc}\n    \"\"\"\n\n"
            f"    _compute = {row['name']!r}\n\n"
            f"    def __init__(self, *, {parameters}):\n"
            f"        super().__init__({arguments})\n\n"
            f"    def compute(self, packing, input=\"<python>\") -> {result}:\n"
            f"        \"\"\"Runs the analysis on ``packing`` (an sbpack.Packing) as sbanalyze "
            f"would; ``input`` names it\n"
            f"        in the results (``file['input']``). The GIL is released; Ctrl-C stops it "
            f"at its next chunk\n"
            f"        (KeyboardInterrupt).\"\"\"\n"
            f"        return {result}(self._analyzer.compute(packing, input))\n")


def _load_extension(path):
    """The built extension alone (the package's __init__ imports what this writes)."""
    spec = importlib.util.spec_from_file_location("_sbpack", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def generate(_sbpack):
    rows = _sbpack.analysis_registry()
    options = _sbpack.analysis_options()
    groups = json.loads(_sbpack.schema_json())["groups"]
    schema = {g["path"].removeprefix("files/<i>/"): g["fields"] for g in groups
              if g["path"].startswith("files/<i>/")}
    schema["file"] = next(g["fields"] for g in groups if g["path"] == "files/<i>")
    titles = {g["path"].removeprefix("files/<i>/"): g["title"] for g in groups}
    parts = ['"""The analyses of sbanalyze as classes, generated at build time by\n'
             'python/generate_analysis_classes.py from sbanalyze\'s registry, option table and '
             'results\nschema (docs/python.md, "Analyses"). Do not edit."""\n',
             "import numpy  # noqa: F401 (the fields' annotations)\n",
             "from .analysis_base import Analysis, Result\n"]
    for row in rows:
        parts.append(_result_class(row, schema, titles))
        parts.append(_analysis_class(row, options))
    classes = ", ".join(row["python_class"] for row in rows)
    parts.append(f"ANALYSES = ({classes},)\n")
    names = [n for row in rows for n in (row["python_class"], row["python_class"] + "Result")]
    parts.append("__all__ = [\"ANALYSES\", " + ", ".join(f'"{n}"' for n in names) + "]\n")
    return "\n\n".join(parts)


if __name__ == "__main__":
    text = generate(_load_extension(sys.argv[1]))
    with open(sys.argv[2], "w") as out:
        out.write(text)
