"""blockdem from Python: scenarios, simulations stepped from Python, numpy views of the state.

The physics is the C++ library's (the extension blockdem._core); see docs/python.md.
"""
from blockdem._core import (  # noqa: F401  (the public API)
    InputError,
    OutputError,
    Scenario,
    Simulation,
    SimulationError,
)

__all__ = ["InputError", "OutputError", "Scenario", "Simulation", "SimulationError"]
