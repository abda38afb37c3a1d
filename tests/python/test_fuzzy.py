"""The Mamdani engine, the paper's controller, configuration and plots; scikit-fuzzy
is the oracle for the inference itself."""

import math

import numpy as np
import pytest

import fgdwa
from fgdwa.fuzzy import engine_from_dict, engine_from_yaml, engine_to_dict, paper_controller_config
from fgdwa.plot.fuzzy import plot_control_surfaces

MF = fgdwa.MembershipFunction
NAN = float("nan")


def raises(match):
    return pytest.raises(fgdwa.FgdwaError, match=match)


def skfuzzy_system(engine):
    """The same system in scikit-fuzzy: the same universes (resolution points per
    domain), terms sampled from the same shapes, the same rules, centroid."""
    fuzz = pytest.importorskip("skfuzzy", reason="scikit-fuzzy is the oracle (pip install '.[test]')")
    ctrl = pytest.importorskip("skfuzzy.control")
    shapes = {"triangle": fuzz.trimf, "trapezoid": fuzz.trapmf,
              "gaussian": lambda x, p: fuzz.gaussmf(x, p[0], p[1])}
    variables = {}
    for kind, group in ((ctrl.Antecedent, engine.inputs), (ctrl.Consequent, engine.outputs)):
        for v in group:
            universe = np.linspace(v.lo, v.hi, engine.resolution)
            var = kind(universe, v.name) if kind is ctrl.Antecedent else kind(universe, v.name, "centroid")
            for name, mf in v.terms.items():
                var[name] = shapes[mf.shape](universe, list(mf.params))
            variables[v.name] = var
    rules = []
    for rule in engine.rules:
        antecedent = None
        for var, term in rule.antecedents:
            antecedent = variables[var][term] if antecedent is None else antecedent & variables[var][term]
        rules.append(ctrl.Rule(antecedent, [variables[var][term] for var, term in rule.consequents]))
    return ctrl.ControlSystemSimulation(ctrl.ControlSystem(rules))


def skfuzzy_evaluate(simulation, **inputs):
    for name, value in inputs.items():
        simulation.input[name] = value
    simulation.compute()
    return dict(simulation.output)


# --------------------------------------------------------------- the oracle

# scikit-fuzzy 0.5 calls np.maximum with a positional `out`, deprecated in numpy 2.
skfuzzy_warnings = pytest.mark.filterwarnings("ignore::DeprecationWarning:skfuzzy.*")


@skfuzzy_warnings
def test_paper_controller_agrees_with_scikit_fuzzy_on_a_21_by_21_grid():
    engine = fgdwa.paper_fuzzy_controller()
    simulation = skfuzzy_system(engine)
    worst = {"beta": 0.0, "delta": 0.0}
    # Every (I, D) fires some rule for both outputs (full rule tables over
    # partitions of unity), so scikit-fuzzy never meets an empty aggregate.
    for i in np.linspace(0.0, 2.0, 21):
        for d in np.linspace(0.0, 5.0, 21):
            ours = engine.evaluate(I=i, D=d)
            theirs = skfuzzy_evaluate(simulation, I=i, D=d)
            for name in worst:
                worst[name] = max(worst[name], abs(ours[name] - theirs[name]))
    # Off the grid too, where the clip corners fall between universe points.
    rng = np.random.default_rng(7)
    for i, d in zip(rng.uniform(-0.2, 2.2, 60), rng.uniform(-0.5, 5.5, 60)):
        ours = engine.evaluate(I=i, D=d)
        theirs = skfuzzy_evaluate(simulation, I=min(max(i, 0.0), 2.0), D=min(max(d, 0.0), 5.0))
        for name in worst:
            worst[name] = max(worst[name], abs(ours[name] - theirs[name]))
    assert worst["beta"] < 1e-3, worst
    assert worst["delta"] < 1e-3, worst


@skfuzzy_warnings
def test_mover_controller_agrees_with_scikit_fuzzy_and_is_the_papers_without_a_contact():
    engine = fgdwa.mover_fuzzy_controller()
    paper = fgdwa.paper_fuzzy_controller()
    assert [v.name for v in engine.inputs] == ["I", "D", "T"]
    assert engine.inputs[2].hi == fgdwa.CONTACT_TIME_RANGE
    simulation = skfuzzy_system(engine)
    rng = np.random.default_rng(11)
    worst = 0.0
    for i, d, t in zip(rng.uniform(0.0, 2.0, 40), rng.uniform(0.0, 5.0, 40), rng.uniform(0.0, 3.0, 40)):
        ours = engine.evaluate(I=i, D=d, T=t)
        theirs = skfuzzy_evaluate(simulation, I=i, D=d, T=t)
        worst = max(worst, *(abs(ours[k] - theirs[k]) for k in ("beta", "delta")))
        # Beta is the paper's whatever T; delta never above it.
        assert ours["beta"] == pytest.approx(paper.evaluate(I=i, D=d)["beta"], abs=1e-12)
        assert ours["delta"] <= paper.evaluate(I=i, D=d)["delta"] + 1e-9
    assert worst < 1e-3, worst
    policy = fgdwa.FuzzyWeights(engine)
    assert policy.weights(1.0, 4.0, math.inf) == fgdwa.FuzzyWeights().weights(1.0, 4.0)
    assert policy.weights(1.0, 4.0, 0.5)["similarity"] < policy.weights(1.0, 4.0, 2.5)["similarity"]
    with raises("contact time"):
        policy.weights(1.0, 4.0, -1.0)
    with raises("contact time"):
        fgdwa.FixedWeights(0.2, 0.5).weights(0.0, 0.0, NAN)


def test_episodes_record_the_contact_time():
    # A disc crossing the robot's way: T is finite while it comes, inf before it is seen and after.
    world = fgdwa.sim.World(grid=fgdwa.OccupancyGrid(np.zeros((40, 80), dtype=bool), 0.1, (0.0, -2.0)),
                            discs=[fgdwa.Disc(center=(4.0, -1.5), radius=0.3, velocity=(0.0, 0.5))])
    result = fgdwa.sim.run_episode(world, (0.5, 0.0, 0.0), (7.5, 0.0), max_steps=60, body="ideal")
    t = result.trace.contact_time
    assert t.shape == result.trace.beta.shape
    assert np.isfinite(t).any() and (t >= 0).all()


@skfuzzy_warnings
def test_mixed_shapes_agree_with_scikit_fuzzy():
    a = fgdwa.FuzzyVariable("a", (-1.0, 1.0), {"neg": MF.trapezoid(-1, -1, -0.6, 0.1), "zero": MF.gaussian(0.1, 0.3),
                                               "pos": MF.triangle(-0.2, 1, 1)})
    b = fgdwa.FuzzyVariable.uniform("b", (0.0, 4.0), ["lo", "hi"])
    y = fgdwa.FuzzyVariable("y", (0.0, 10.0), {"small": MF.gaussian(2.0, 1.5), "mid": MF.trapezoid(3, 4.5, 6, 7.5),
                                              "big": MF.triangle(6, 10, 10)})
    engine = fgdwa.MamdaniEngine([a, b], [y], [
        "IF a is neg THEN y is small",
        "IF a is zero AND b is lo THEN y is mid",
        "IF a is zero AND b is hi THEN y is big",
        "IF a is pos THEN y is big",
        "IF b is hi AND a is neg THEN y is mid",
    ])
    simulation = skfuzzy_system(engine)
    worst = 0.0
    # The Gaussian keeps some rule firing at every input.
    for va in np.linspace(-1.0, 1.0, 9):
        for vb in np.linspace(0.0, 4.0, 9):
            worst = max(worst, abs(engine.evaluate(a=va, b=vb)["y"] - skfuzzy_evaluate(simulation, a=va, b=vb)["y"]))
    assert worst < 1e-3


# ---------------------------------------------------------------- the preset

def test_paper_controller_shape_and_corners():
    engine = fgdwa.paper_fuzzy_controller()
    assert engine.input_names == ["I", "D"]
    assert engine.output_names == ["beta", "delta"]
    assert [v.domain for v in engine.inputs + engine.outputs] == [(0, 2), (0, 5), (0, 1), (0, 5)]
    assert len(engine.rules) == 9
    assert engine.inputs[1].terms["M"] == MF.triangle(0, 2.5, 5)
    # One rule fires fully at each corner: a shoulder's centroid is a third of its base in.
    corners = {(0, 0): (1 / 6, 2.5 / 3), (2, 0): (5 / 6, 2.5 / 3), (0, 5): (1 / 6, 5 - 2.5 / 3), (2, 5): (0.5, 2.5)}
    for (i, d), (beta, delta) in corners.items():
        out = engine.evaluate(I=i, D=d)
        assert out["beta"] == pytest.approx(beta, abs=1e-12)
        assert out["delta"] == pytest.approx(delta, abs=1e-12)


def test_paper_config_builds_the_same_engine_and_round_trips():
    preset = fgdwa.paper_fuzzy_controller()
    from_config = engine_from_dict(paper_controller_config())
    round_trip = engine_from_dict(engine_to_dict(preset))
    grid = np.meshgrid(np.linspace(-0.5, 2.5, 13), np.linspace(-1, 6, 15))
    want = preset.evaluate_grid(*grid)
    for engine in (from_config, round_trip):
        got = engine.evaluate_grid(*grid)
        for name in ("beta", "delta"):
            np.testing.assert_array_equal(got[name], want[name])
    assert [str(r) for r in round_trip.rules] == [str(r) for r in preset.rules]
    assert engine_to_dict(round_trip) == engine_to_dict(preset)


# -------------------------------------------------------------- the engine

def test_inputs_are_clamped_and_no_rule_gives_the_midpoint():
    engine = fgdwa.paper_fuzzy_controller()
    assert engine.evaluate(I=-4, D=99) == engine.evaluate(I=0, D=5)
    assert engine.evaluate(I=math.inf, D=-math.inf) == engine.evaluate(I=2, D=0)
    lonely = fgdwa.MamdaniEngine([fgdwa.FuzzyVariable.uniform("x", (0, 1), ["lo", "hi"])],
                                 [fgdwa.FuzzyVariable.uniform("y", (2, 6))], ["IF x is hi THEN y is L"])
    assert lonely.evaluate(x=0.0) == {"y": 4.0}
    assert lonely.firing_strengths(x=0.0) == [0.0]
    assert lonely.evaluate(x=0.5)["y"] > 5.0


def test_evaluate_by_position_or_name_and_bad_inputs():
    engine = fgdwa.paper_fuzzy_controller()
    assert engine.evaluate(0.3, 1.1) == engine.evaluate(I=0.3, D=1.1) == engine.evaluate(0.3, D=1.1)
    assert engine.evaluate(np.float32(0.5), np.int64(2)) == engine.evaluate(I=0.5, D=2.0)
    with raises("missing input 'D'"):
        engine.evaluate(I=1.0)
    with raises("unknown input 'gamma'"):
        engine.evaluate(I=1.0, D=1.0, gamma=1.0)
    with raises("input I given twice"):
        engine.evaluate(1.0, I=1.0, D=1.0)
    with raises("at most 2 inputs"):
        engine.evaluate(1.0, 2.0, 3.0)
    with raises("input D = nan"):
        engine.evaluate(I=1.0, D=NAN)
    with raises("input I: expected a number, got str"):
        engine.evaluate(I="1", D=1.0)
    with raises("input I: expected a number, got bool"):
        engine.evaluate(I=True, D=1.0)
    with raises("input D = nan"):
        engine.firing_strengths(I=1.0, D=NAN)


def test_evaluate_grid_broadcasts_and_matches_evaluate():
    engine = fgdwa.paper_fuzzy_controller()
    i_axis, d_axis = np.linspace(0, 2, 7), np.linspace(0, 5, 4)
    out = engine.evaluate_grid(I=i_axis[None, :], D=d_axis[:, None])
    assert out["beta"].shape == out["delta"].shape == (4, 7)
    assert out["beta"].dtype == np.float64
    for r, d in enumerate(d_axis):
        for c, i in enumerate(i_axis):
            single = engine.evaluate(I=i, D=d)
            assert out["beta"][r, c] == single["beta"]
            assert out["delta"][r, c] == single["delta"]
    scalar = engine.evaluate_grid(0.5, [1.0, 2.0, 3.0])  # a scalar broadcasts too
    assert scalar["beta"].shape == (3,)
    assert engine.evaluate_grid([], [])["beta"].shape == (0,)
    with raises("do not broadcast"):
        engine.evaluate_grid(np.zeros(3), np.zeros(4))
    with raises("input D: element 1 is nan"):
        engine.evaluate_grid([0.0, 1.0], [0.0, NAN])
    with raises("input I: expected numbers"):
        engine.evaluate_grid(["a"], [1.0])
    with raises("missing input 'D'"):
        engine.evaluate_grid(I=[1.0])


def test_membership_functions():
    tri = MF.triangle(0, 1, 3)
    assert [tri(x) for x in (-1, 0, 0.5, 1, 2, 3)] == [0, 0, 0.5, 1, 0.5, 0]
    np.testing.assert_allclose(tri(np.array([[0.5, 2.0]])), [[0.5, 0.5]])
    assert MF.triangle(0, 0, 1)(0.0) == 1.0 and MF.triangle(0, 1, 1)(1.0) == 1.0
    assert MF.trapezoid(0, 1, 2, 4)(3.0) == 0.5
    assert MF.gaussian(1.0, 0.5)(1.5) == pytest.approx(math.exp(-0.5))
    assert tri.shape == "triangle" and tri.params == (0.0, 1.0, 3.0)
    assert repr(MF.gaussian(1, 2)) == "MembershipFunction.gaussian(1.0, 2.0)"
    with raises("a <= b <= c"):
        MF.triangle(0, 2, 1)
    with raises("a < c"):
        MF.triangle(1, 1, 1)
    with raises("a <= b <= c <= d"):
        MF.trapezoid(0, 2, 1, 3)
    with raises("sigma"):
        MF.gaussian(0, 0)
    with raises("finite"):
        MF.triangle(0, NAN, 1)
    with raises("x: expected a number, got bool"):
        tri(True)


def test_variables_and_rules():
    v = fgdwa.FuzzyVariable.uniform("D", (0, 5))
    assert v.term_names == ["S", "M", "L"]
    assert v.membership("M", 1.25) == 0.5
    assert "FuzzyVariable('D', (0.0, 5.0)" in repr(v)
    pairs = fgdwa.FuzzyVariable("x", [0, 1], [("a", MF.triangle(0, 0, 1)), ("b", MF.triangle(0, 1, 1))])
    assert pairs.term_names == ["a", "b"]
    with raises("no term 'X'"):
        v.membership("X", 1.0)
    with raises("variable x domain = \\[1, 0\\]"):
        fgdwa.FuzzyVariable("x", (1, 0), {"a": MF.triangle(0, 0, 1)})
    with raises("variable x domain: expected \\(lo, hi\\)"):
        fgdwa.FuzzyVariable("x", 1.0, {"a": MF.triangle(0, 0, 1)})
    with raises("variable x terms\\['a'\\]: expected a MembershipFunction, got tuple"):
        fgdwa.FuzzyVariable("x", (0, 1), {"a": (0, 0, 1)})
    with raises("variable x term far = triangle\\(2, 3, 4\\): is zero everywhere"):
        fgdwa.FuzzyVariable("x", (0, 1), {"far": MF.triangle(2, 3, 4)})
    with raises("variable name = 'two words'"):
        fgdwa.FuzzyVariable("two words", (0, 1), {"a": MF.triangle(0, 0, 1)})
    rule = fgdwa.FuzzyRule({"I": "S", "D": "M"}, {"beta": "S"})
    assert str(rule) == "IF I is S AND D is M THEN beta is S"
    assert rule.antecedents == [("I", "S"), ("D", "M")]
    assert repr(fgdwa.FuzzyRule("if I is S then beta is L")) == "FuzzyRule('IF I is S THEN beta is L')"
    with raises("expected 'is' after 'I'"):
        fgdwa.FuzzyRule("IF I = S THEN beta is L")
    with raises("rule antecedents term: expected a str, got int"):
        fgdwa.FuzzyRule({"I": 1}, {"beta": "S"})


def test_engine_construction_errors_name_the_culprit():
    i = fgdwa.FuzzyVariable.uniform("I", (0, 2))
    beta = fgdwa.FuzzyVariable.uniform("beta", (0, 1))
    with raises("rule 0 'IF I is X THEN beta is S': variable I has no term 'X' \\(terms: S, M, L\\)"):
        fgdwa.MamdaniEngine([i], [beta], ["IF I is X THEN beta is S"])
    with raises("unknown input variable 'Q'"):
        fgdwa.MamdaniEngine([i], [beta], ["IF Q is S THEN beta is S"])
    with raises("beta is an output"):
        fgdwa.MamdaniEngine([i], [beta], ["IF beta is S THEN beta is S"])
    with raises("variable name 'I' is used twice"):
        fgdwa.MamdaniEngine([i, i], [beta], ["IF I is S THEN beta is S"])
    with raises("rules\\[1\\]: expected a FuzzyRule or a rule string, got int"):
        fgdwa.MamdaniEngine([i], [beta], ["IF I is S THEN beta is S", 3])
    with raises("inputs: expected FuzzyVariable items"):
        fgdwa.MamdaniEngine(["I"], [beta], ["IF I is S THEN beta is S"])
    with raises("resolution = 2"):
        fgdwa.MamdaniEngine([i], [beta], ["IF I is S THEN beta is S"], resolution=2)
    with raises("rules: the engine needs at least one rule"):
        fgdwa.MamdaniEngine([i], [beta], [])


# ------------------------------------------------------------ configuration

def small_config():
    return {
        "inputs": {"x": {"domain": [0, 1]}},
        "outputs": {"y": {"domain": [0, 10], "terms": {"S": "uniform", "M": {"gaussian": [5, 1]}, "L": "uniform"}}},
        "rules": ["IF x is S THEN y is S", {"if": {"x": "M"}, "then": {"y": "M"}}, "IF x is L THEN y is L"],
    }


def test_engine_from_dict_defaults_and_term_overrides():
    engine = engine_from_dict(small_config())
    assert engine.resolution == 1001
    assert engine.inputs[0].terms["S"] == MF.triangle(0, 0, 0.5)
    y = engine.outputs[0].terms
    assert y["S"] == MF.triangle(0, 0, 5) and y["M"] == MF.gaussian(5, 1) and y["L"] == MF.triangle(5, 10, 10)
    assert engine.evaluate(x=0.5)["y"] == pytest.approx(5.0, abs=1e-12)
    two = engine_from_dict({**small_config(), "inputs": {"x": {"domain": [0, 1], "terms": ["S", "M", "L"]}},
                            "resolution": 201})
    assert two.resolution == 201


def without(config, *path):
    *parents, last = path
    node = config
    for key in parents:
        node = node[key]
    del node[last]
    return config


def replaced(config, value, *path):
    *parents, last = path
    node = config
    for key in parents:
        node = node[key]
    node[last] = value
    return config


@pytest.mark.parametrize("config,match", [
    (replaced(small_config(), 1, "extra"), "fuzzy configuration: unknown key 'extra'"),
    (without(small_config(), "rules"), "missing key 'rules'"),
    (replaced(small_config(), "many", "resolution"), "resolution: expected an integer, got str"),
    (replaced(small_config(), True, "resolution"), "resolution: expected an integer, got bool"),
    (replaced(small_config(), 2, "resolution"), "resolution = 2"),
    (replaced(small_config(), [1, 2], "inputs"), "inputs: expected a mapping, got list"),
    (replaced(small_config(), {}, "inputs"), "inputs: needs at least one variable"),
    (replaced(small_config(), [0, 1], "inputs", "x", "domian"), "inputs.x: unknown key 'domian'"),
    (without(small_config(), "inputs", "x", "domain"), "inputs.x: missing key 'domain'"),
    (replaced(small_config(), [0], "inputs", "x", "domain"), "inputs.x.domain: expected 2 numbers, got 1"),
    (replaced(small_config(), "0..1", "inputs", "x", "domain"), "inputs.x.domain: expected a list of 2 numbers"),
    (replaced(small_config(), [0, "1e-3"], "inputs", "x", "domain"), "inputs.x.domain\\[1\\]: expected a number"),
    (replaced(small_config(), [1, 0], "inputs", "x", "domain"), "variable x domain = \\[1, 0\\]: needs lo < hi"),
    (replaced(small_config(), 3, "inputs", "x", "terms"), "inputs.x.terms: expected a mapping, got int"),
    (replaced(small_config(), {"triangel": [0, 1, 2]}, "outputs", "y", "terms", "M"),
     "outputs.y.terms.M: unknown shape 'triangel'"),
    (replaced(small_config(), {"triangle": [0, 1]}, "outputs", "y", "terms", "M"),
     "outputs.y.terms.M.triangle: expected 3 numbers, got 2"),
    (replaced(small_config(), {"triangle": [3, 2, 1]}, "outputs", "y", "terms", "M"),
     "outputs.y.terms.M: .*a <= b <= c"),
    (replaced(small_config(), {"gaussian": [5, 1], "triangle": [0, 1, 2]}, "outputs", "y", "terms", "M"),
     "outputs.y.terms.M: expected one shape"),
    (replaced(small_config(), "round", "outputs", "y", "terms", "M"), "outputs.y.terms.M: expected a mapping"),
    (replaced(small_config(), "IF x is S THEN y is S", "rules"), "rules: expected a list of rules, got str"),
    (replaced(small_config(), "IF x is S", "rules", 0), "rules\\[0\\]: rule 'IF x is S': no THEN part"),
    (replaced(small_config(), {"if": {"x": "S"}}, "rules", 1), "rules\\[1\\]: missing key 'then'"),
    (replaced(small_config(), {"if": {"x": "S"}, "then": {"y": "S"}, "else": {}}, "rules", 1),
     "rules\\[1\\]: unknown key 'else'"),
    (replaced(small_config(), {"if": {"x": True}, "then": {"y": "S"}}, "rules", 1),
     "rules\\[1\\].if.x: expected a name \\(str\\), got bool"),
    (replaced(small_config(), {"if": {"x": "XL"}, "then": {"y": "S"}}, "rules", 1),
     "variable x has no term 'XL'"),
    (replaced(small_config(), 7, "rules", 2), "rules\\[2\\]: expected a mapping, got int"),
])
def test_engine_from_dict_rejects(config, match):
    with raises(match):
        engine_from_dict(config)


YAML = """
resolution: 501
inputs:
  I: {domain: [0, 2]}
  D: {domain: [0, 5], terms: [S, M, L]}
outputs:
  beta:
    domain: [0, 1]
    terms:
      S: {triangle: [0, 0, 0.5]}
      M: {triangle: [0, 0.5, 1]}
      L: {trapezoid: [0.5, 1, 1, 1]}
rules:
  - IF I is S THEN beta is S
  - IF I is M THEN beta is M
  - {if: {I: L, D: S}, then: {beta: L}}
  - IF I is L AND D is M THEN beta is M
  - IF I is L AND D is L THEN beta is M
"""


def test_engine_from_yaml_text_and_file(tmp_path):
    engine = engine_from_yaml(YAML)
    assert engine.resolution == 501
    assert engine.outputs[0].terms["L"] == MF.trapezoid(0.5, 1, 1, 1)
    path = tmp_path / "fuzzy.yaml"
    path.write_text(YAML)
    for source in (path, str(path)):
        assert engine_to_dict(engine_from_yaml(source)) == engine_to_dict(engine)
    assert engine.evaluate(I=2, D=0)["beta"] == pytest.approx(1 - 0.5 / 3, abs=1e-12)


def test_engine_from_yaml_errors(tmp_path):
    with raises("fuzzy configuration: malformed YAML at line 1"):
        engine_from_yaml("inputs: [unclosed")
    with raises("expected a mapping at the top level, got str \\(no file named 'missing.yaml'\\)"):
        engine_from_yaml("missing.yaml")
    with raises("expected a mapping at the top level, got list"):
        engine_from_yaml("- 1\n- 2\n")
    with raises("outputs.beta: unknown key 'domian'"):
        engine_from_yaml(YAML.replace("    domain: [0, 1]", "    domian: [0, 1]"))
    with raises("expected a path or YAML text, got int"):
        engine_from_yaml(3)


# ------------------------------------------------------------------ plotting

@pytest.mark.parametrize("kind", ["surface", "heatmap"])
def test_plot_control_surfaces_writes_a_png(tmp_path, kind):
    path = tmp_path / "plots" / f"surfaces_{kind}.png"
    plot_control_surfaces(fgdwa.paper_fuzzy_controller(), path, kind=kind, points=21)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert path.stat().st_size > 10_000


def test_plot_control_surfaces_accepts_a_preset_or_config(tmp_path):
    import matplotlib.pyplot as plt

    fig = plot_control_surfaces("paper", points=11)
    titles = [ax.get_title() for ax in fig.axes if ax.get_title()]
    assert titles == ["beta(I, D)", "delta(I, D)"]
    plt.close(fig)
    plot_control_surfaces(paper_controller_config(), tmp_path / "config.png", kind="heatmap", points=11)
    assert (tmp_path / "config.png").exists()
    with raises("exactly 2 inputs"):
        plot_control_surfaces(small_config())
    with raises("kind = 'pie'"):
        plot_control_surfaces("paper", kind="pie")
    with raises("points = 1"):
        plot_control_surfaces("paper", points=1)
    with raises("expected a MamdaniEngine, a configuration mapping or 'paper'"):
        plot_control_surfaces("papr")
