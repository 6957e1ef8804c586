"""Theories of pouring as data: the model (rules, facts, superiority,
settings, provenance), its two file formats (native facts and DFL), reading
the learned theory, and families of theories for benchmarks."""
