"""Layer 3: metrics measured from trajectories."""
