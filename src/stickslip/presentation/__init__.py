"""Presentation of a run: figures drawn from datasets (``plots``, ``fe_plots``, ``fe_paper_figures``,
``methods_plots``), the notebooks' helpers (``notebook``), the replication page (``page``, ``sources``,
``show``) and the report's captions (``report``). Nothing in the science imports this package."""
