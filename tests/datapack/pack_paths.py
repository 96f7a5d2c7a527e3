"""Shared paths for the datapack tests."""
from pathlib import Path

PACK = Path(__file__).resolve().parents[2] / "datapack"
FUNCTIONS = sorted(PACK.glob("data/*/function/**/*.mcfunction"))


def function_id(path: Path) -> str:
    """`data/<ns>/function/a/b.mcfunction` -> `<ns>:a/b`."""
    rel = path.relative_to(PACK / "data")
    namespace, _, *rest = rel.parts
    return f"{namespace}:" + "/".join(rest)[: -len(".mcfunction")]
