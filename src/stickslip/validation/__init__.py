"""Checks of the switch-model solver: limit-cycle quantities, textbook closed forms, an independent peer
program (SUNDIALS CVODE through scikit-sundae), and the Fig. 17 round trip."""
