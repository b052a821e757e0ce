"""Reference replication of a stick-slip friction vibration study.

Layers, each importing only from the ones listed before it:
``model``, ``solvers``, ``analysis``, ``fe``, ``io``.
"""

__version__ = "0.1.0"
