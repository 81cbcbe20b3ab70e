"""The type stub (bouncelab/__init__.pyi) names every attribute and key the package hands
out, and a key it promises always (a TypedDict's required key) is always there: an editor
completes what exists and a type checker accepts what the package returns."""

import ast
import inspect
import pydoc
from pathlib import Path

import pytest

import bouncelab
from test_bouncelab import no_user_presets  # noqa: F401

STUB = Path(bouncelab.__file__).with_name("__init__.pyi")


def stub_classes():
    """{class: (bases, {name: required}, total)} of the stub's classes."""
    classes = {}
    for node in ast.parse(STUB.read_text()).body:
        if isinstance(node, ast.ClassDef):
            total = not any(k.arg == "total" and not k.value.value for k in node.keywords)
            names = {}
            for m in node.body:
                if isinstance(m, ast.AnnAssign):
                    names[m.target.id] = total
                elif isinstance(m, ast.FunctionDef):
                    names[m.name] = False
            classes[node.name] = ([ast.unparse(b) for b in node.bases], names)
    return classes


def declared(name, classes=None):
    """{name: required} of a stub class with its bases'."""
    classes = classes or stub_classes()
    bases, names = classes[name]
    out = {}
    for b in bases:
        if b in classes:
            out.update(declared(b, classes))
    return {**out, **names}


def test_every_name_the_stub_takes_from_a_module_exists():
    # `npt.Array`, which numpy.typing never had, made `Floats` an error for a type checker
    import numpy
    import numpy.typing
    import os
    import typing

    modules = {"np": numpy, "npt": numpy.typing, "os": os, "typing": typing}
    tree = ast.parse(STUB.read_text())
    used = {(n.value.id, n.attr) for n in ast.walk(tree)
            if isinstance(n, ast.Attribute) and isinstance(n.value, ast.Name)
            and n.value.id in modules}
    assert used, "the stub takes nothing from a module?"
    missing = [f"{m}.{a}" for m, a in sorted(used) if not hasattr(modules[m], a)]
    assert not missing, missing


FUNCTIONS = [n for n in bouncelab.__all__ if not isinstance(getattr(bouncelab, n), type)]


def stub_functions():
    return {n.name: n for n in ast.parse(STUB.read_text()).body if isinstance(n, ast.FunctionDef)}


def unpacked(kwarg):
    """`**ball: Unpack[BallArguments]` (or `**flight: Unpack[FlightArguments]`, its fields and
    its base's) as the keyword-only arguments it types, each with the default None: what the
    runtime signature spells out."""
    if kwarg is None:
        return []
    hint = ast.unparse(kwarg.annotation)
    assert hint.startswith("Unpack[") and hint.endswith("]"), hint
    fields = declared(hint[len("Unpack["):-1])
    none = ast.Constant(None)
    return [(ast.arg(arg=f), none, inspect.Parameter.KEYWORD_ONLY) for f in fields]


def test_the_ball_arguments_are_typed_once():
    # issue 55 item 1: the ball's keyword arguments are one TypedDict, not a block in each
    # function that takes them
    tree = ast.parse(STUB.read_text())
    takes = [n.name for n in tree.body if isinstance(n, ast.FunctionDef) and n.args.kwarg]
    assert len(takes) >= 15, takes
    for n in tree.body:
        if isinstance(n, ast.FunctionDef):
            assert "k_p" not in [a.arg for a in n.args.kwonlyargs + n.args.args] or \
                n.name in ("run_params", "impacts"), n.name


@pytest.mark.parametrize("name", FUNCTIONS)
def test_the_stub_and_help_give_each_function_as_it_is(name):
    # help() shows the runtime signature: a default pyo3 cannot spell was "Ellipsis" there
    # (collide's target_stiffness, run_params' z_p, monte_carlo's samples)
    f = getattr(bouncelab, name)
    real = inspect.signature(f).parameters
    assert "Ellipsis" not in pydoc.render_doc(f, renderer=pydoc.plaintext)
    a = stub_functions()[name].args
    positional = a.posonlyargs + a.args
    stub = [(p, d, inspect.Parameter.POSITIONAL_OR_KEYWORD)
            for p, d in zip(positional, [None] * (len(positional) - len(a.defaults)) + a.defaults)]
    stub += [(p, d, inspect.Parameter.KEYWORD_ONLY) for p, d in zip(a.kwonlyargs, a.kw_defaults)]
    # the arguments the stub spells out in the runtime's order; a TypedDict's (keyword-only,
    # their order no caller sees) each once among the rest, wherever the runtime puts them
    typed = unpacked(a.kwarg)
    names = [p.arg for p, _, _ in typed]
    assert len(set(names)) == len(names), names
    assert [p.arg for p, _, _ in stub] == [n for n in real if n not in names]
    assert set(names) <= set(real), set(names) - set(real)
    for p, default, kind in stub + typed:
        r = real[p.arg]
        assert r.kind == kind, (p.arg, r.kind)
        if default is None:
            assert r.default is inspect.Parameter.empty, p.arg
        else:
            assert eval(ast.unparse(default), {"float": float}) == r.default, p.arg


def history():
    return bouncelab.run(preset="golf", v0=3.0, history=True, samples=200)


RESULTS = {
    "Impact": lambda: history(),
    "Collision": lambda: bouncelab.collide(preset="baseball", v0=40.0, target_mass=0.8),
    "ObliqueImpact": lambda: bouncelab.oblique("tennis", angle=20.0, friction=0.5,
                                               history=True, samples=10),
}


@pytest.mark.parametrize("name", RESULTS)
def test_every_attribute_of_a_result_is_in_the_stub(name):
    r = RESULTS[name]()
    real = {k for k in dir(r) if not k.startswith("_")}
    assert real <= set(declared(name)), real - set(declared(name))


DICTS = {
    "trace": ("MultiFit", lambda: bouncelab.fit_trace(history().t, history().force,
                                                      preset="golf", v0=3.0)),
    "cor table": ("MultiFit", lambda: bouncelab.fit_cor_table(
        [1.0, 2.0, 4.0, 8.0], [0.85, 0.84, 0.83, 0.8], cor_sd=[0.01] * 4)),
    "drops": ("MultiFit", lambda: bouncelab.fit_drops([1.0, 2.0], [0.6, 1.1])),
    "monte carlo": ("MonteCarlo", lambda: bouncelab.monte_carlo(
        preset="golf", vary="k_p=5%", samples=100, return_samples=True)),
    "drop": ("Drop", lambda: bouncelab.drop(preset="tennis", standard="itf", bounces=2)),
    "oblique fit": ("ObliqueFit", lambda: bouncelab.fit_oblique(
        v0=[20.0] * 3, angle_deg=[30.0, 40.0, 50.0], spin_in=[0.0] * 3,
        vx_out=[15.0, 14.0, 13.0], vy_out=[5.0, 6.0, 7.0], preset="tennis")),
    "standard": ("Standard", lambda: bouncelab.standards()[0]),
    "static": ("Static", lambda: bouncelab.static("tennis", load_kg=8.165)),
    "court": ("Court", lambda: bouncelab.court("tennis", surface="clay", friction=0.55,
                                                  surface_cor=0.75)),
    "preset": ("Preset", lambda: bouncelab.presets()[0]),
    "surface": ("SurfaceObject", lambda: bouncelab.oblique("tennis", angle=30.0, friction=0.6,
                                                           tangential_damping=2.0).surface),
}
# a key Python cannot spell as a TypedDict field (a keyword): the docstring names it
UNSPELLABLE = {"lambda", "return"}


@pytest.mark.parametrize("case", DICTS)
def test_every_key_of_a_returned_dict_is_in_the_stub_and_every_required_one_is_there(case):
    name, call = DICTS[case]
    d, keys = call(), declared(name)
    assert set(d) - UNSPELLABLE <= set(keys), set(d) - UNSPELLABLE - set(keys)
    required = {k for k, r in keys.items() if r}
    assert required <= set(d), required - set(d)
