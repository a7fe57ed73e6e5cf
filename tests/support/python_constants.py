"""The top-level constants of a Python file, read without running it: the tests that hold a
standalone Python copy (tests/dut/pxdut_numpy.py) to the C headers it mirrors use it
(tests/dut/wire_table_check.py, tests/spec/spec_copies_check.py)."""
import ast


def python_constants(path):
    """NAME -> value of the module's top-level literal assignments (A = 1, A = B = (1, 2),
    A, B = 1, "x"); None for a name assigned something that is not a literal."""
    out = {}

    def value(node):
        try:
            return ast.literal_eval(node)
        except ValueError:
            return None

    for node in ast.parse(open(path, encoding="utf-8").read()).body:
        if not isinstance(node, ast.Assign):
            continue
        for target in node.targets:
            if isinstance(target, ast.Name):
                out[target.id] = value(node.value)
            elif isinstance(target, ast.Tuple) and isinstance(node.value, ast.Tuple):
                for t, v in zip(target.elts, node.value.elts):
                    if isinstance(t, ast.Name):
                        out[t.id] = value(v)
    return out
