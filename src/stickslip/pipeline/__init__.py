"""Orchestration support: what the workflow layer needs to know about the package and its config files
(which source files a job runs, how config files are read). No science here."""
