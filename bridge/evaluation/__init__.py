"""Measuring a learned theory against its own oracle: held-out scenes,
measures, baselines (a decision tree, random exploration), the evaluation's
stages, and the report with its plots."""
