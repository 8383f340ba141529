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
# Studies and the analysis helpers (python/bind_study.cpp, bind_analysis.cpp, study.py).
from blockdem._core import (  # noqa: F401
    Motion,
    housner_rocking,
    integrate_record,
    intensity_measures,
    limit_analysis,
    process_record,
    read_record,
    response_spectrum,
    rigid_plastic_sliding,
)
from blockdem.study import sweep  # noqa: F401

__all__ = ["InputError", "OutputError", "Scenario", "Simulation", "SimulationError",
           "Motion", "housner_rocking", "integrate_record", "intensity_measures", "limit_analysis", "process_record", "read_record",
           "response_spectrum", "rigid_plastic_sliding", "sweep"]
