"""Inverse study: which parameter sets reproduce each figure's reported numbers, how far they are
from the stated ones, and which single misprint explains most of them. A fit beside the claims table."""
