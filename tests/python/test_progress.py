"""progress= of the long calls (atlas, boundary_loci, synth_points, fit, tolerance with samples): a
function f(done, total)
sees done rising to total, a tqdm bar ends at its total, and an exception the callback raises
propagates out of the call."""
import pytest

import sphtroch


def three_points():
    _, P = sphtroch.GearTrain(1.0, 2.0, "1/2", phase=0.3).trace(samples=400)
    return P[[7, 111, 290]], P[::10]


CALLS = {
    "atlas": lambda progress: sphtroch.atlas(2, grid=24, threads=2, progress=progress),
    "boundary_loci": lambda progress: sphtroch.boundary_loci(2, steps=40, threads=2, progress=progress),
    "synth_points": lambda progress: sphtroch.synth_points(three_points()[0], ratios=(2, 2), progress=progress),
    "fit": lambda progress: sphtroch.fit(three_points()[1], ratios=(2, 2), candidates=1, progress=progress),
    "tolerance": lambda progress: sphtroch.GearTrain(1.0, 2.0, 2).tolerance(da2=1e-3, da3=1e-3, samples=7,
                                                                             progress=progress),
}
# cells, a2 samples, the ratios of ratios=(2, 2) (--ratios 2,2: +-1, +-2, +-1/2)
# and the Monte Carlo trains of tolerance(samples=7).
UNITS = {"atlas": 24 * 24, "boundary_loci": 40, "synth_points": 6, "fit": 6, "tolerance": 7}


@pytest.mark.parametrize("name", sorted(CALLS))
def test_a_counting_callable_sees_monotone_done_ending_at_total(name):
    seen = []
    CALLS[name](lambda done, total: seen.append((done, total)))
    assert seen, name
    assert all(total == UNITS[name] for _, total in seen), seen
    done = [d for d, _ in seen]
    assert done == sorted(done) and done[-1] == UNITS[name], seen
    assert len(seen) <= UNITS[name] + 1


@pytest.mark.parametrize("name", sorted(CALLS))
def test_an_exception_in_the_callback_propagates(name):
    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop(f"{done}/{total}")

    with pytest.raises(Stop):
        CALLS[name](stop)


@pytest.mark.parametrize("name", sorted(CALLS))
def test_a_tqdm_bar_ends_at_its_total(name):
    tqdm = pytest.importorskip("tqdm")
    with tqdm.tqdm(disable=False, file=open("/dev/null", "w")) as bar:
        CALLS[name](bar)
        assert bar.total == UNITS[name] and bar.n == UNITS[name]


def test_anything_else_is_refused_naming_progress():
    with pytest.raises(sphtroch.InvalidInput, match="progress") as e:
        sphtroch.synth_points(three_points()[0], n=2, progress=5)
    assert e.value.field == "progress"
