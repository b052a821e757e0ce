"""Presentation of a run: figures drawn from datasets (``plots``, ``fe_plots``, ``methods_plots``), the
notebooks' helpers (``notebook``) and the replication page (``page``, ``sources``, ``show``) and the report's captions (``report``). Nothing in
the science imports this package."""
