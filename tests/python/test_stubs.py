"""The typed stubs (gfield/__init__.pyi) name what the module holds, and every public name has
a docstring."""

import ast
import inspect
import pathlib

import gfield


def stub_names():
    stub = pathlib.Path(gfield.__file__).with_suffix(".pyi")
    tree = ast.parse(stub.read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
    return {n for n in names if not n.startswith("_")}


def test_stubs_name_the_public_api():
    public = set(gfield.__all__)
    assert public == {n for n in dir(gfield) if not n.startswith("_")}
    typed_dicts = {"Hits", "ExactHits", "Comparison"}  # the dicts' shapes, stubs only
    assert stub_names() == public | typed_dicts


def test_every_public_name_is_documented():
    for name in gfield.__all__:
        item = getattr(gfield, name)
        assert inspect.getdoc(item), name
        if inspect.isclass(item):
            for member, value in vars(item).items():
                if not member.startswith("_"):
                    assert inspect.getdoc(value), f"{name}.{member}"
