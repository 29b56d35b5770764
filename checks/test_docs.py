"""The schema in the repository: docs/catalog.schema.json is what the pydantic models give, and
docs/catalog.md documents every field they have."""

from __future__ import annotations

import json
from pathlib import Path

from reference.schema import Claim, Excluded, Meta, Slip, json_schema

DOCS = Path(__file__).parents[1] / "docs"


def test_the_json_schema_is_generated_from_the_models() -> None:
    committed = json.loads((DOCS / "catalog.schema.json").read_text(encoding="utf-8"))
    assert committed == json_schema(), (
        "regenerate docs/catalog.schema.json from reference.schema.json_schema() "
        "(the command is in docs/catalog.md)"
    )


def test_every_field_is_documented() -> None:
    text = (DOCS / "catalog.md").read_text(encoding="utf-8")
    for model in (Meta, Claim, Excluded, Slip):
        for name, field in model.model_fields.items():
            assert f"`{field.alias or name}`" in text, (model.__name__, name)
