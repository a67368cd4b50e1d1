"""Safe function strings of ``t, x, y, z, X, Y, Z`` (Kratos ``GenericFunctionUtility``).

A function string such as ``"-2.0e-1*t"`` or ``"0.01*sin(pi*x)*t"`` is parsed once with :mod:`ast`,
checked against a whitelist and compiled into a small Python function; nothing of the string is
ever handed to ``eval`` unchecked. Allowed:

* numbers (integers are read as doubles, as in the C++ evaluator), the variables ``t`` (TIME),
  ``x, y, z`` (current coordinates), ``X, Y, Z`` (initial coordinates) and the constants ``pi``,
  ``e``;
* ``+ - * / ** %``, unary ``+``/``-``, comparisons, ``and``/``or``/``not``, ``a if c else b``;
* calls of ``sin cos tan asin acos atan atan2 sinh cosh tanh exp log log10 sqrt abs pow min max
  floor ceil``.

Everything else (attribute access, subscripts, other names, lambdas, comprehensions, strings, ...)
is an :class:`~contact_app.InputError` that quotes the expression and says where it was found.
``^`` is refused too: Kratos' C++ evaluator reads it as a power, its older Python one as XOR.
Arithmetic is done in doubles, so ``9**9**9**9`` cannot run away: constant parts are folded when
the string is compiled and an overflow there is reported at once.
"""

from __future__ import annotations

import ast
import copy
import math
from collections.abc import Callable
from functools import reduce
from typing import Any, cast

import numpy as np

from .._core import InputError
from ..json_input import quote
from ..parameters import suggest

#: Names of the variables a function string may use, in the order the compiled function takes them.
VARIABLES: tuple[str, ...] = ("t", "x", "y", "z", "X", "Y", "Z")
SPACE_VARIABLES = frozenset({"x", "y", "z", "X", "Y", "Z"})
CONSTANTS: dict[str, float] = {"pi": math.pi, "e": math.e}
MAX_LENGTH = 4000
#: Deepest nesting of the expression tree (a chain of 900 "+" is 900 levels deep; checking and
#: compiling recurse over the tree, so the depth is bounded before they run).
MAX_DEPTH = 100


def _np_min(*args: Any) -> Any:
    return reduce(np.minimum, args)


def _np_max(*args: Any) -> Any:
    return reduce(np.maximum, args)


def _np_log(value: Any, base: Any = None) -> Any:
    return np.log(value) if base is None else np.log(value) / np.log(base)


def _floor(value: float) -> float:
    return float(math.floor(value))


def _ceil(value: float) -> float:
    return float(math.ceil(value))


# name -> (minimum arguments, maximum arguments or None, scalar version, numpy version)
FUNCTIONS: dict[str, tuple[int, int | None, Callable[..., Any], Callable[..., Any]]] = {
    "sin": (1, 1, math.sin, np.sin),
    "cos": (1, 1, math.cos, np.cos),
    "tan": (1, 1, math.tan, np.tan),
    "asin": (1, 1, math.asin, np.arcsin),
    "acos": (1, 1, math.acos, np.arccos),
    "atan": (1, 1, math.atan, np.arctan),
    "atan2": (2, 2, math.atan2, np.arctan2),
    "sinh": (1, 1, math.sinh, np.sinh),
    "cosh": (1, 1, math.cosh, np.cosh),
    "tanh": (1, 1, math.tanh, np.tanh),
    "exp": (1, 1, math.exp, np.exp),
    "log": (1, 2, math.log, _np_log),
    "log10": (1, 1, math.log10, np.log10),
    "sqrt": (1, 1, math.sqrt, np.sqrt),
    "abs": (1, 1, abs, np.abs),
    "pow": (2, 2, math.pow, np.power),
    "min": (2, None, min, _np_min),
    "max": (2, None, max, _np_max),
    "floor": (1, 1, _floor, np.floor),
    "ceil": (1, 1, _ceil, np.ceil),
}

_BINARY = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "**", ast.Mod: "%"}
_UNARY = (ast.UAdd, ast.USub, ast.Not)
_COMPARE = (ast.Eq, ast.NotEq, ast.Lt, ast.LtE, ast.Gt, ast.GtE)
_FORBIDDEN = {
    ast.Attribute: "attribute access (a.b)",
    ast.Subscript: "subscripts (a[i])",
    ast.Lambda: "lambda functions",
    ast.ListComp: "comprehensions",
    ast.SetComp: "comprehensions",
    ast.DictComp: "comprehensions",
    ast.GeneratorExp: "comprehensions",
    ast.JoinedStr: "f-strings",
    ast.List: "lists",
    ast.Tuple: "tuples",
    ast.Set: "sets",
    ast.Dict: "dictionaries",
    ast.NamedExpr: "assignments (:=)",
    ast.Starred: "starred arguments (*a)",
    ast.Await: "await",
    ast.Yield: "yield",
    ast.YieldFrom: "yield",
    ast.Slice: "slices",
}
_OPERATOR_HINTS = {
    ast.BitXor: 'write "**" for a power (Kratos versions disagree whether "^" is a power or XOR)',
    ast.FloorDiv: 'write "floor(a/b)"',
    ast.BitAnd: 'write "and"',
    ast.BitOr: 'write "or"',
    ast.Invert: 'write "not" or "-"',
    ast.MatMult: 'write "*"',
}
_ALLOWED_SUMMARY = (
    "an expression of t, x, y, z, X, Y, Z with numbers, + - * / ** %, comparisons, and/or/not, "
    '"a if c else b", the constants pi and e and the functions ' + ", ".join(FUNCTIONS)
)


class FunctionExpression:
    """A compiled, checked function string ``f(t, x, y, z, X, Y, Z)``.

    Args:
        expression: the text, e.g. ``"-2.0e-1*t"``.
        where: where it was found (``ProjectParameters.json › processes › ... › value``), for
            messages.

    Raises:
        InputError: the text is not valid Python syntax, uses anything outside the whitelist of the
            module docstring, or a constant part of it overflows.
    """

    def __init__(self, expression: str, where: str = "") -> None:
        self._expression = expression
        self._where = where
        body = self._parse()
        self._names: set[str] = set()
        self._check(body)
        body = _Folder(self).visit(body)
        self._scalar = self._compile(body, numpy=False)
        self._vectorisable = all(
            not isinstance(node, ast.BoolOp | ast.IfExp | ast.Compare)
            and not (isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not))
            for node in ast.walk(body)
        )
        self._vector = self._compile(body, numpy=True) if self._vectorisable else None

    # -- properties --

    @property
    def expression(self) -> str:
        """The text as written."""
        return self._expression

    @property
    def depends_on_space(self) -> bool:
        """True if any of x, y, z, X, Y, Z appears."""
        return bool(self._names & SPACE_VARIABLES)

    @property
    def depends_on_time(self) -> bool:
        """True if t appears."""
        return "t" in self._names

    def DependsOnSpace(self) -> bool:
        """Kratos name of :attr:`depends_on_space`."""
        return self.depends_on_space

    # -- evaluation --

    def __call__(
        self,
        t: float = 0.0,
        x: float = 0.0,
        y: float = 0.0,
        z: float = 0.0,
        X: float = 0.0,  # noqa: N803 - the names users write
        Y: float = 0.0,  # noqa: N803
        Z: float = 0.0,  # noqa: N803
    ) -> float:
        """Return the value at one point and time.

        Raises:
            InputError: the value is not a finite number there (division by zero, sqrt of a
                negative number, overflow, ...).
        """
        point = (t, x, y, z, X, Y, Z)
        try:
            value = float(self._scalar(*point))
        except (ArithmeticError, ValueError, TypeError) as error:
            raise self._evaluation_error(point, str(error)) from None
        if not math.isfinite(value):
            raise self._evaluation_error(point, f"the result is {value}")
        return value

    def CallFunction(
        self,
        x: float,
        y: float,
        z: float,
        t: float,
        X: float = 0.0,  # noqa: N803
        Y: float = 0.0,  # noqa: N803
        Z: float = 0.0,  # noqa: N803
    ) -> float:
        """Kratos argument order ``(x, y, z, t, X, Y, Z)`` of :meth:`__call__`."""
        return self(t, x, y, z, X, Y, Z)

    def values_at(self, t: float, current: np.ndarray, initial: np.ndarray) -> np.ndarray:
        """Return the values at many points at time ``t``.

        Args:
            t: the time.
            current: (n, 3) current coordinates (x, y, z).
            initial: (n, 3) initial coordinates (X, Y, Z).

        Returns:
            (n,) values.

        Raises:
            InputError: a value is not a finite number (the message names the first such point).
        """
        count = len(current)
        if not self.depends_on_space:
            return np.full(count, self(t))
        if self._vector is not None:
            columns = (t, *current.T, *initial.T)
            try:
                with np.errstate(divide="raise", invalid="raise", over="ignore", under="ignore"):
                    values = np.broadcast_to(
                        np.asarray(self._vector(*columns), dtype=float), (count,)
                    ).copy()
                if np.all(np.isfinite(values)):
                    return values
            except (ArithmeticError, ValueError, TypeError):
                pass  # evaluated point by point below, which names the offending point
        return np.array([self(t, *p, *q) for p, q in zip(current, initial, strict=True)])

    # -- compilation --

    def _error(self, what: str, fix: str = "") -> InputError:
        where = f"\n  where:    {self._where}" if self._where else ""
        text = (
            f'the function string "{quote(self._expression)}" {what}{where}\n'
            f"  expected: {_ALLOWED_SUMMARY}"
        )
        if fix:
            text += f"\n  fix:      {fix}"
        return InputError(text)

    def _evaluation_error(self, point: tuple[float, ...], reason: str) -> InputError:
        values = ", ".join(
            f"{name}={value:g}" for name, value in zip(VARIABLES, point, strict=True)
        )
        where = f"\n  where:    {self._where}" if self._where else ""
        return InputError(
            f'the function string "{quote(self._expression)}" has no finite value at {values}: '
            f"{reason}{where}\n"
            "  fix:      change the expression so that it is defined on the whole model part"
        )

    def _parse(self) -> ast.expr:
        if not isinstance(self._expression, str) or not self._expression.strip():
            raise self._error("is empty", "write an expression such as 0.1*t")
        if len(self._expression) > MAX_LENGTH:
            raise self._error(
                f"is {len(self._expression)} characters long",
                f"keep it below {MAX_LENGTH} characters",
            )
        try:
            body = ast.parse(self._expression.strip(), mode="eval").body
        except SyntaxError as error:
            column = f" at column {error.offset}" if error.offset else ""
            raise self._error(f"is not a valid expression ({error.msg}{column})") from None
        except RecursionError:
            raise self._too_deep() from None
        except (MemoryError, ValueError) as error:
            raise self._error(f"cannot be parsed ({type(error).__name__})") from None
        if _depth(body) > MAX_DEPTH:
            raise self._too_deep()
        return body

    def _too_deep(self) -> InputError:
        return self._error(
            f"is nested more than {MAX_DEPTH} levels deep (operators and parentheses)",
            "split the sum into fewer terms, or use a table or a CSV file for long data",
        )

    def _check(self, node: ast.AST) -> None:
        """Walk the tree and refuse every node outside the whitelist."""
        if isinstance(node, ast.Constant):
            value = node.value
            if isinstance(value, bool) or not isinstance(value, int | float):
                kind = "string literals" if isinstance(value, str | bytes) else repr(value)
                raise self._error(f"uses {kind}, which is not allowed", "use numbers only")
        elif isinstance(node, ast.Name):
            self._check_name(node.id)
        elif isinstance(node, ast.Call):
            self._check_call(node)
        elif isinstance(node, ast.BinOp):
            if type(node.op) not in _BINARY:
                self._refuse_operator(node.op)
            self._check(node.left)
            self._check(node.right)
        elif isinstance(node, ast.UnaryOp):
            if not isinstance(node.op, _UNARY):
                self._refuse_operator(node.op)
            self._check(node.operand)
        elif isinstance(node, ast.Compare):
            if not all(isinstance(op, _COMPARE) for op in node.ops):
                raise self._error(
                    "uses an identity or membership test (is, in), which is not allowed",
                    "compare numbers with <, <=, >, >=, == or !=",
                )
            for operand in (node.left, *node.comparators):
                self._check(operand)
        elif isinstance(node, ast.BoolOp):
            for operand in node.values:
                self._check(operand)
        elif isinstance(node, ast.IfExp):
            for operand in (node.test, node.body, node.orelse):
                self._check(operand)
        else:
            what = _FORBIDDEN.get(type(node), f"{type(node).__name__} expressions")
            raise self._error(f"uses {what}, which is not allowed")

    def _refuse_operator(self, operator: ast.AST) -> None:
        symbol = {
            ast.BitXor: "^",
            ast.FloorDiv: "//",
            ast.BitAnd: "&",
            ast.BitOr: "|",
            ast.Invert: "~",
            ast.MatMult: "@",
            ast.LShift: "<<",
            ast.RShift: ">>",
        }.get(type(operator), type(operator).__name__)
        raise self._error(
            f'uses the operator "{symbol}", which is not allowed',
            _OPERATOR_HINTS.get(type(operator), "use + - * / ** %"),
        )

    def _check_name(self, name: str) -> None:
        if name in VARIABLES:
            self._names.add(name)
            return
        if name in CONSTANTS:
            return
        if name in FUNCTIONS:
            raise self._error(
                f'uses the function "{name}" without calling it', f"write {name}(...)"
            )
        allowed = [*VARIABLES, *CONSTANTS, *FUNCTIONS]
        hint = suggest(name, allowed)
        if name.startswith("__"):
            what = f'uses the name "{name}"; names with leading underscores are not allowed'
        else:
            what = f'uses the unknown name "{name}"'
        raise self._error(what, hint or "use only " + ", ".join(f'"{n}"' for n in allowed))

    def _check_call(self, node: ast.Call) -> None:
        if not isinstance(node.func, ast.Name):
            what = _FORBIDDEN.get(type(node.func), "a call of a computed value")
            raise self._error(f"calls through {what}, which is not allowed")
        name = node.func.id
        if name not in FUNCTIONS:
            hint = suggest(name, list(FUNCTIONS))
            raise self._error(
                f'calls "{name}", which is not an allowed function',
                hint or "call one of " + ", ".join(FUNCTIONS),
            )
        if node.keywords:
            raise self._error(f'passes keyword arguments to "{name}", which is not allowed')
        low, high, _, _ = FUNCTIONS[name]
        count = len(node.args)
        if count < low or (high is not None and count > high):
            if high is None:
                expected = f"{low} or more"
            else:
                expected = f"{low}" if low == high else f"{low} or {high}"
            raise self._error(f'calls "{name}" with {count} arguments; it takes {expected}')
        for argument in node.args:
            self._check(argument)

    def _compile(self, body: ast.expr, numpy: bool) -> Callable[..., Any]:
        """Wrap the checked body into ``lambda t, x, y, z, X, Y, Z: body`` and compile it."""
        body = _PowerToCall().visit(copy.deepcopy(body))
        arguments = ast.arguments(
            posonlyargs=[],
            args=[ast.arg(arg=name) for name in VARIABLES],
            kwonlyargs=[],
            kw_defaults=[],
            defaults=[],
        )
        tree = ast.Expression(body=ast.Lambda(args=arguments, body=body))
        ast.fix_missing_locations(tree)
        index = 3 if numpy else 2
        namespace: dict[str, Any] = {name: row[index] for name, row in FUNCTIONS.items()}
        namespace["_pow"] = np.power if numpy else math.pow
        namespace["__builtins__"] = {}
        try:
            code = compile(tree, "<function string>", "eval")
        except (RecursionError, MemoryError, ValueError) as error:
            raise self._error(f"cannot be compiled ({type(error).__name__})") from None
        return eval(code, namespace)  # noqa: S307 - the tree was checked against the whitelist


class _PowerToCall(ast.NodeTransformer):
    """Turn ``a ** b`` into ``_pow(a, b)``: math.pow raises where float ** returns complex."""

    def visit_BinOp(self, node: ast.BinOp) -> ast.expr:  # noqa: N802 - ast visitor name
        self.generic_visit(node)
        if isinstance(node.op, ast.Pow):
            return ast.Call(
                func=ast.Name(id="_pow", ctx=ast.Load()), args=[node.left, node.right], keywords=[]
            )
        return node


def _depth(tree: ast.AST) -> int:
    """Depth of an expression tree, walked without recursion."""
    deepest, pending = 0, [(tree, 1)]
    while pending:
        node, level = pending.pop()
        deepest = max(deepest, level)
        pending.extend((child, level + 1) for child in ast.iter_child_nodes(node))
    return deepest


class _Folder(ast.NodeTransformer):
    """Read integers as doubles, replace pi/e by their values and fold constant sub-expressions."""

    def __init__(self, owner: FunctionExpression) -> None:
        self._owner = owner

    def visit_Constant(self, node: ast.Constant) -> ast.expr:  # noqa: N802
        try:
            # _check admitted only int and float constants (not bool): the cast states it for mypy.
            value = float(cast("int | float", node.value))
        except OverflowError:
            value = math.inf
        if not math.isfinite(value):
            raise self._owner._error(
                f'has the number "{ast.unparse(node)[:40]}", which is not a finite double',
                "write a number below 1.8e308",
            )
        return ast.copy_location(ast.Constant(value=value), node)

    def visit_Name(self, node: ast.Name) -> ast.expr:  # noqa: N802
        if node.id in CONSTANTS:
            return ast.copy_location(ast.Constant(value=CONSTANTS[node.id]), node)
        return node

    def generic_visit(self, node: ast.AST) -> ast.AST:
        node = super().generic_visit(node)
        if isinstance(node, ast.expr) and not isinstance(node, ast.Constant | ast.Name):
            if all(not isinstance(sub, ast.Name) or sub.id in FUNCTIONS for sub in ast.walk(node)):
                return self._fold(node)
        return node

    def _fold(self, node: ast.expr) -> ast.expr:
        text = ast.unparse(node)
        function = self._owner._compile(node, numpy=False)
        try:
            value = float(function(*([0.0] * len(VARIABLES))))
        except (ArithmeticError, ValueError, TypeError) as error:
            raise self._owner._error(
                f'has the constant part "{text}", which cannot be evaluated in double precision '
                f"({error})",
                "simplify the constant part",
            ) from None
        if not math.isfinite(value):
            raise self._owner._error(
                f'has the constant part "{text}", which evaluates to {value}',
                "simplify the constant part",
            )
        return ast.copy_location(ast.Constant(value=value), node)
