"""mechmodel: the reference physics of *Classical Mechanics with a BANG!*, Unit 1.

One module or package per topic (design section 5 of ../shared/design.md; the map is
docs/architecture.md), each function citing the book's equation or figure.
Pure functions: no files read, nothing imported from the rest of bangcheck, no number copied from
the book. Formulas use plain operators, so they work on floats, ``fractions.Fraction`` and mpmath
numbers alike (each docstring says which); exact arithmetic only where the inputs ask for it.
Physical inputs are validated with a clear ``ValueError``.
"""
