"""The config models, one module per config file (``config_models`` assembles them and re-exports every
name)."""
