"""Subcommands of `pantarhei`, one module per group (see bridge/cli.py)."""
