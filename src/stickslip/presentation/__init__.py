"""Presentation of a run: the replication page (``results/index.html``) and its verdict rule."""
