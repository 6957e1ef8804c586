"""The bridge: SWI-Prolog (through pyswip) and clingo hosted from Python,
the oracle exposed to the logic side, and the `pantarhei` command."""
