"""reference: the catalog of the book's numeric claims and everything that judges them.

The catalog (``reference/claims/chNN.toml``), the book's identity, the units and constants
tables, the tokenizer and scan, validation, comparison, input intervals and diagnosis.
``evaluate()`` returns the evaluated claims.
"""

from reference.evaluation import EvaluatedClaim, Evaluation, evaluate

__all__ = ["EvaluatedClaim", "Evaluation", "evaluate"]
