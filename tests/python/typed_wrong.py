"""A typed user script with six mistakes `mypy --strict` must report (tests/python/test_typing.py):
the lines marked "error:" and only those."""
import sphtroch

train: sphtroch.GearTrain = sphtroch.GearTrain(1.0, 2.0, None)  # error: None is no gear ratio
t, p = train.trace(samples=2.5)  # error: samples is a whole number
d = sphtroch.atlas(2, grid="64")  # error: grid is a count, not text
x: int = train.a2  # error: a2 is a float
nodes: int = train.classify()["counts"]["node"]  # error: a misspelt key of the Counts TypedDict
upper: float = sphtroch.Clinostat(1.33, 2).worst_window_mean(600)["upper_s"]  # error: a misspelt key of WorstWindowMean
