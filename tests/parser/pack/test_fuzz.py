"""Any JSON shape in pack.mcmeta, tag and advancement files becomes diagnostics, never an exception."""
import json

from hypothesis import HealthCheck, given, settings, strategies as st

from mcfunction_parser.pack.loader import load_packs
from tests.parser.pack.packbuild import write_pack

KEYS = st.sampled_from(["pack", "pack_format", "description", "supported_formats", "min_format",
                        "max_format", "min_inclusive", "max_inclusive", "overlays", "entries",
                        "directory", "formats", "values", "replace", "id", "required", "rewards",
                        "function", "text", "extra", "filter", "block", "namespace", "path"])
SCALARS = st.one_of(st.none(), st.booleans(), st.integers(-3, 100), st.floats(allow_nan=False),
                    st.sampled_from(["", "a:x", "#a:t", "ov", "A:B", "a:missing", "x y", "(", ".*"]))
JSON = st.recursive(SCALARS, lambda inner: st.one_of(
    st.lists(inner, max_size=4), st.dictionaries(KEYS, inner, max_size=4)), max_leaves=12)


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(meta=JSON, tag_file=JSON, advancement=JSON, version=st.sampled_from([None, "1.20.4", "1.21.11"]))
def test_any_json_shape_is_diagnosed_not_raised(tmp_path_factory, meta, tag_file, advancement, version):
    root = write_pack(tmp_path_factory.mktemp("p"), {
        "data/a/function/x.mcfunction": "say x\n",
        "data/a/functions/x.mcfunction": "say x\n",
        "data/a/tags/function/t.json": json.dumps(tag_file),
        "data/a/tags/functions/t.json": json.dumps(tag_file),
        "data/a/advancement/adv.json": json.dumps(advancement),
        "ov/data/a/function/y.mcfunction": "say y\n",
    }, json.dumps({"pack": meta}) if isinstance(meta, dict) else json.dumps(meta))
    loaded = load_packs([root], mc_version=version)
    assert all(d.severity in ("error", "warning", "info") and d.path for d in loaded.diagnostics)
    for tag_id in loaded.tags:
        assert set(loaded.resolve_tag(tag_id)) <= set(loaded.functions)
