#!/usr/bin/env python3
"""Writes docs/python-api.md, the Python package's reference, from its docstrings; --check fails (exit 1) when the
page differs from what the package says (ctest PythonApiDoc).

    PYTHONPATH=build/python /usr/bin/python3 scripts/python_api_doc.py [--check]
"""
import inspect
import os
import sys

import strandfem

PAGE = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "docs", "python-api.md")


def signature(obj):
    try:
        return str(inspect.signature(obj))
    except (TypeError, ValueError):
        return "(...)"


def entry(name, obj, level):
    doc = inspect.getdoc(obj) or ""
    lines = [f"{'#' * level} `{name}{signature(obj) if callable(obj) and not isinstance(obj, type) else ''}`", ""]
    if doc:
        lines += [doc, ""]
    return lines


def page():
    lines = ["# Python API reference", "",
             "Generated from the package's docstrings by `scripts/python_api_doc.py`; the guide is "
             "[python.md](python.md). Units: N, mm, MPa; EI in N mm² in `references`, N m² where a name says so.", ""]
    for name in strandfem.__all__:
        obj = getattr(strandfem, name)
        if name == "__version__" or name == "CaseError":
            continue
        if inspect.ismodule(obj):
            lines += [f"## `strandfem.{name}`", "", inspect.getdoc(obj) or "", ""]
            for member, value in inspect.getmembers(obj, inspect.isfunction):
                if not member.startswith("_") and value.__module__ == obj.__name__:
                    lines += entry(f"{name}.{member}", value, 3)
        elif isinstance(obj, type):
            lines += [f"## `strandfem.{name}`", "", inspect.getdoc(obj) or "", ""]
            for member, value in vars(obj).items():
                if member.startswith("_"):
                    continue
                if isinstance(value, (classmethod, staticmethod)):
                    lines += entry(f"{name}.{member}", getattr(obj, member), 3)
                elif isinstance(value, property):
                    doc = inspect.getdoc(value)
                    lines += [f"### `{name}.{member}` (property)", ""] + ([doc, ""] if doc else [])
                elif inspect.isfunction(value):
                    lines += entry(f"{name}.{member}", value, 3)
        else:
            lines += [f"## `strandfem.{name}{signature(obj)}`", "", inspect.getdoc(obj) or "", ""]
    lines += ["## `strandfem.CaseError`", "", "Bad input: a `ValueError` whose message names the key and `file:line:column`.", ""]
    return "\n".join(line.rstrip() for line in lines).rstrip() + "\n"


def main():
    text = page()
    if "--check" in sys.argv:
        current = open(PAGE, encoding="utf-8").read() if os.path.exists(PAGE) else ""
        if current != text:
            print(f"{PAGE} is not what the docstrings say: run scripts/python_api_doc.py")
            return 1
        return 0
    with open(PAGE, "w", encoding="utf-8") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
