"""The contact application's Python layer (installed as ``contact_app.contact``).

Contact processes named in ``ProjectParameters.json`` (ALM, penalty, mesh tying, MPC), the search
base they share, and (later) the contact solvers and the contact convergence-criteria factory.
"""
