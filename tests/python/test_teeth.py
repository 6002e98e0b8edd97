"""GearTrain(..., teeth="ZS:ZP"): the train of n = ZS/ZP, the counts kept (not reduced) and echoed
next to n in reports, the JSON and repr, through pickling; exactly one of n and teeth. Expected
values: the same train made with n = ZS/ZP, and the CLI's own output for --teeth."""
import pickle
import subprocess

import pytest
import sphtroch
from conftest import EXE


def test_teeth_is_the_train_of_the_reduced_ratio_and_is_kept():
    by_teeth = sphtroch.GearTrain(0.7, 2.5, teeth="39:15")
    by_n = sphtroch.GearTrain(0.7, 2.5, "13/5")
    assert by_teeth == by_n  # the curve depends on n only
    assert by_teeth.ratio == "13/5" and by_teeth.teeth == "39:15" and by_n.teeth is None
    assert by_teeth.trace(samples=64)[1].tolist() == by_n.trace(samples=64)[1].tolist()
    assert repr(by_teeth) == "GearTrain(a2='0.7', a3='2.5', teeth='39:15', phase='0')"
    assert by_teeth.texts[2] == "13/5"
    internal = sphtroch.GearTrain(1.0, 2.0, teeth="-24:12")
    assert internal.ratio == "-2" and internal.teeth == "-24:12"


def test_reports_echo_the_teeth_as_the_cli_does():
    train = sphtroch.GearTrain(0.7, 2.5, teeth="39:15")
    assert train.classify()["inputs"]["teeth"] == "39:15"
    assert "n = 13/5 (teeth 39:15)" in train.report()
    cli = subprocess.run([EXE, "classify", "--a2", "0.7", "--a3", "2.5", "--teeth", "39:15"],
                         capture_output=True, text=True, check=True).stdout
    def masked(text):  # the work line ends with the wall time
        return [line for line in text.splitlines() if not line.startswith("work:")]
    assert masked(train.report()) == masked(cli)


def test_pickle_keeps_the_teeth():
    train = sphtroch.GearTrain("pi/3", "ap", teeth="36:12", phase="pi/4")
    back = pickle.loads(pickle.dumps(train))
    assert back == train and back.teeth == "36:12" and repr(back) == repr(train)


@pytest.mark.parametrize("kwargs,field", [(dict(n="13/5", teeth="39:15"), "teeth"), (dict(), "n"),
                                          (dict(teeth="39:0"), "teeth"), (dict(teeth=39), "teeth"),
                                          (dict(teeth="39"), "teeth"), (dict(teeth="2000:1"), "teeth")])
def test_exactly_one_of_n_and_teeth(kwargs, field):
    with pytest.raises(sphtroch.InvalidInput) as info:
        sphtroch.GearTrain(0.7, 2.5, **kwargs)
    assert info.value.field == field, str(info.value)
