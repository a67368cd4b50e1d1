"""Function strings: arithmetic and math results, vectorised evaluation, and refused forms."""

from __future__ import annotations

import math
import time

import numpy as np
import pytest

import contact_app as ca
from contact_app.processes.function_expression import FunctionExpression

WHERE = "ProjectParameters.json › processes › loads_process_list › [0] › Parameters › value"


@pytest.mark.parametrize(
    ("text", "point", "expected"),
    [
        ("-2.0e-1*t", {"t": 0.5}, -0.1),
        ("3*t", {"t": 2.0}, 6.0),
        ("1/2", {}, 0.5),  # integers are doubles: no integer division
        ("7 % 3 + 2**3 - -1", {}, 10.0),
        ("sin(pi*x)*cos(0) + exp(0) + log(e) + log10(100) + sqrt(16)", {"x": 0.5}, 9.0),
        (
            "atan2(y, x) + abs(-2) + pow(2, 10) + min(t, 3, 4) + max(1, t)",
            {"x": 1, "y": 1, "t": 2},
            math.pi / 4 + 2 + 1024 + 2 + 2,
        ),
        ("floor(2.7) + ceil(2.1) + tanh(0) + sinh(0) + cosh(0) + asin(1)", {}, 6 + math.pi / 2),
        ("1 if t > 0.5 and not x < 0 else 2", {"t": 0.7, "x": 1.0}, 1.0),
        ("1 if t > 0.5 or x > 0 else 2", {"t": 0.1, "x": -1.0}, 2.0),
        ("0 <= t < 1", {"t": 0.5}, 1.0),
        (
            "X + 10*Y + 100*Z - x - 10*y - 100*z",
            {"X": 1, "Y": 2, "Z": 3, "x": 1.5, "y": 2, "z": 3},
            -0.5,
        ),
    ],
)
def test_function_expression_evaluates_like_math(
    text: str, point: dict[str, float], expected: float
) -> None:
    assert FunctionExpression(text)(**point) == pytest.approx(expected, rel=1e-14)


def test_function_expression_dependencies_and_kratos_call_order() -> None:
    time_only = FunctionExpression("0.2*t")
    spatial = FunctionExpression("x*t + Y")
    assert time_only.depends_on_time and not time_only.depends_on_space
    assert spatial.DependsOnSpace() and spatial.depends_on_time
    assert not FunctionExpression("2.5").depends_on_time
    # Kratos order: (x, y, z, t, X, Y, Z)
    assert spatial.CallFunction(2.0, 0.0, 0.0, 3.0, 0.0, 5.0, 0.0) == 11.0


def test_function_expression_vectorised_values_match_pointwise() -> None:
    rng = np.random.default_rng(4)
    current, initial = rng.uniform(0.1, 2, (50, 3)), rng.uniform(0.1, 2, (50, 3))
    for text in ("sin(x)*y**2 + sqrt(Z) - max(x, Y)/3", "1 if x > 1 else -y", "7.5"):
        function = FunctionExpression(text)
        values = function.values_at(0.3, current, initial)
        pointwise = [function(0.3, *p, *q) for p, q in zip(current, initial, strict=True)]
        np.testing.assert_allclose(values, pointwise, rtol=1e-14)


def test_function_expression_undefined_value_names_the_point() -> None:
    function = FunctionExpression("sqrt(x - 1)", WHERE)
    points = np.array([[2.0, 0, 0], [0.5, 0, 0]])
    with pytest.raises(ca.InputError, match=r"no finite value at t=0, x=0\.5") as error:
        function.values_at(0.0, points, points)
    assert WHERE in str(error.value)
    with pytest.raises(ca.InputError, match="division by zero"):
        FunctionExpression("1/t")(t=0.0)
    with pytest.raises(ca.InputError, match="the result is inf"):
        FunctionExpression("t*1e308*10")(t=1.0)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("__import__('os').system('ls')", "attribute access"),
        ("__import__('os')", 'calls "__import__", which is not an allowed function'),
        ("__builtins__", "names with leading underscores are not allowed"),
        ("t.real", r"attribute access \(a\.b\)"),
        ("x.__class__.__mro__", "attribute access"),
        ("t[0]", r"subscripts \(a\[i\]\)"),
        ("(lambda: 1)()", "calls through lambda functions"),
        ("lambda t: t", "lambda functions"),
        ("[t for t in (1, 2)]", "comprehensions"),
        ("sum(i for i in (1, 2))", 'calls "sum"'),
        ("'abc'", "string literals"),
        ("f'{t}'", "f-strings"),
        ("(1, 2)", "tuples"),
        ("(y := 2)", r"assignments \(:=\)"),
        ("t if t in (1,) else 0", "identity or membership"),
        ("open('/etc/passwd')", 'calls "open"'),
        ("eval('1')", 'calls "eval"'),
        ("True", "True, which is not allowed"),
        ("1j", "1j, which is not allowed"),
        ("sin(t, x=1)", "keyword arguments"),
        ("sin(*t)", "starred"),
        ("pow(t)", 'calls "pow" with 1 arguments; it takes 2'),
        ("sin", 'uses the function "sin" without calling it'),
        ("t^2", 'write "\\*\\*" for a power'),
        ("t//2", 'write "floor\\(a/b\\)"'),
        ("t +", "is not a valid expression"),
        ("", "is empty"),
    ],
)
def test_function_expression_refuses_forbidden_forms(text: str, message: str) -> None:
    with pytest.raises(ca.InputError, match=message) as error:
        FunctionExpression(text, WHERE)
    assert f'the function string "{text}"' in str(error.value)
    assert f"where:    {WHERE}" in str(error.value)


def test_function_expression_unknown_name_suggests_the_allowed_names() -> None:
    with pytest.raises(ca.InputError, match='did you mean "sin"'):
        FunctionExpression("sinn(t)")
    with pytest.raises(ca.InputError, match='unknown name "time"') as error:
        FunctionExpression("2*time")
    assert 'did you mean "tanh"' in str(error.value) or '"t", "x", "y"' in str(error.value)
    with pytest.raises(ca.InputError, match='use only "t", "x", "y", "z", "X", "Y", "Z", "pi"'):
        FunctionExpression("qqqq")


@pytest.mark.parametrize("text", ["9**9**9**9", "t**9**9**9", "2**(2**2000)", "exp(1e6)*t"])
def test_function_expression_power_tower_is_refused_quickly(text: str) -> None:
    start = time.perf_counter()
    with pytest.raises(ca.InputError, match="constant part"):
        FunctionExpression(text)
    assert time.perf_counter() - start < 0.5


@pytest.mark.parametrize("text", ["1" + "0" * 400, "1e400*t"])
def test_function_expression_numbers_beyond_double_are_refused(text: str) -> None:
    with pytest.raises(ca.InputError, match="not a finite double"):
        FunctionExpression(text)


def test_function_expression_runtime_overflow_is_an_error_not_a_hang() -> None:
    function = FunctionExpression("t**t**t")
    with pytest.raises(ca.InputError, match="no finite value"):
        function(t=9.0)


def test_function_expression_deep_nesting_and_length_are_refused() -> None:
    with pytest.raises(ca.InputError):
        FunctionExpression("(" * 500 + "t" + ")" * 500)
    with pytest.raises(ca.InputError, match="characters long"):
        FunctionExpression("+".join(["t"] * 3000))


@pytest.mark.parametrize("terms", [900, 600])
def test_deeply_nested_expressions_are_bounded(terms: int) -> None:
    text = "+".join(["x"] * terms) if terms == 900 else "*".join(["(t+1)"] * terms)
    with pytest.raises(ca.InputError, match="nested more than 100 levels deep") as failure:
        FunctionExpression(text, "here")
    assert len(str(failure.value)) < 1000  # the expression is quoted briefly
