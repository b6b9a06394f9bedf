#!/usr/bin/env python3
"""denoise_trade.py — the figures of docs/trade/denoise.md from the PFMs denoise_trade.sh made:
relMSE of the raw and the denoised image against the reference (the formula of
host/image/error_metrics.h), less the reference's own noise (E[(x − r)²] = E[(x − μ)²] + Var r
for an independent reference: the raw error is c/n + N, so the two highest sample counts give
the reference's share N), N_eq = spp × relMSE_raw ÷
relMSE_denoised, relMSE × process CPU time; and PNG pictures (raw, denoised, reference, error
maps) with only the standard library.

    denoise_trade.py table WORK SCENE SPPS...        one CSV line per spp on stdout
    denoise_trade.py pictures WORK SCENE SPP OUTDIR  raw, denoised, reference, error maps
"""
import math
import struct
import sys
import zlib

EPSILON = 1e-2  # kRelMseEpsilon


def read_pfm(path):
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            raise SystemExit(f"{path}: not an RGB PFM")
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = f.read()
    endian = "<" if scale < 0 else ">"
    values = struct.unpack(f"{endian}{width * height * 3}f", data[: width * height * 12])
    rows = [values[y * width * 3:(y + 1) * width * 3] for y in range(height)]
    rows.reverse()  # PFM is bottom row first
    return width, height, [v for row in rows for v in row]


def per_pixel_error(image, reference):
    return [
        sum((image[i + c] - reference[i + c]) ** 2 / (reference[i + c] ** 2 + EPSILON)
            for c in range(3)) / 3.0
        for i in range(0, len(reference), 3)
    ]


def rel_mse(image, reference):
    errors = per_pixel_error(image, reference)
    return sum(errors) / len(errors)


def seconds(path):
    wall, user, system = open(path).read().split()[-3:]
    return float(wall), float(user) + float(system)


def reference_noise(raw_errors):
    """The reference's share N of every relMSE, from the raw errors at the two highest sample
    counts n1 < n2 on the line e = c/n + N."""
    (n1, e1), (n2, e2) = sorted(raw_errors.items())[-2:]
    c = (e1 - e2) / (1.0 / n1 - 1.0 / n2)
    return max(e2 - c / n2, 0.0)


def table(work, scene, spps):
    _, _, reference = read_pfm(f"{work}/{scene}_ref.pfm")
    raw_errors = {int(spp): rel_mse(read_pfm(f"{work}/{scene}_{spp}_raw.pfm")[2], reference)
                  for spp in spps}
    noise = reference_noise(raw_errors)
    print(f"# {scene}: reference noise {noise:.3e} (subtracted)")
    print("scene,spp,relmse_raw,relmse_denoised,n_eq,cpu_raw,cpu_denoised,"
          "relmse_x_cpu_raw,relmse_x_cpu_denoised,denoise_wall")
    for spp in spps:
        _, _, raw = read_pfm(f"{work}/{scene}_{spp}_raw.pfm")
        _, _, denoised = read_pfm(f"{work}/{scene}_{spp}_denoised.pfm")
        e_raw = rel_mse(raw, reference) - noise
        e_den = rel_mse(denoised, reference) - noise
        _, cpu_render = seconds(f"{work}/{scene}_{spp}_render.time")
        _, cpu_denoise = seconds(f"{work}/{scene}_{spp}_denoise.time")
        denoise_wall = float(open(f"{work}/{scene}_{spp}_denoise.seconds").read())
        cpu_den = cpu_render + cpu_denoise
        print(f"{scene},{spp},{e_raw:.4e},{e_den:.4e},{int(spp) * e_raw / e_den:.1f},"
              f"{cpu_render:.2f},{cpu_den:.2f},{e_raw * cpu_render:.4e},{e_den * cpu_den:.4e},"
              f"{denoise_wall:.3f}")


def write_png(path, width, height, rgb_bytes):
    raw = b"".join(b"\x00" + bytes(rgb_bytes[y * width * 3:(y + 1) * width * 3])
                   for y in range(height))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def srgb(value):
    value = min(max(value, 0.0), 1.0)
    encoded = 12.92 * value if value <= 0.0031308 else 1.055 * value ** (1 / 2.4) - 0.055
    return int(round(encoded * 255))


def heat(value):
    """log10 of a pixel's relative squared error, 1e-5 (black) to 1 (white): black, red,
    yellow, white."""
    t = min(max((math.log10(max(value, 1e-12)) + 5.0) / 5.0, 0.0), 1.0)
    r = min(1.0, 3 * t)
    g = min(1.0, max(0.0, 3 * t - 1))
    b = min(1.0, max(0.0, 3 * t - 2))
    return [int(255 * r), int(255 * g), int(255 * b)]


def pictures(work, scene, spp, outdir):
    width, height, reference = read_pfm(f"{work}/{scene}_ref.pfm")
    images = {
        "raw": read_pfm(f"{work}/{scene}_{spp}_raw.pfm")[2],
        "denoised": read_pfm(f"{work}/{scene}_{spp}_denoised.pfm")[2],
    }
    write_png(f"{outdir}/denoise-{scene}-reference.png", width, height,
              [srgb(v) for v in reference])
    for kind, image in images.items():
        write_png(f"{outdir}/denoise-{scene}-{spp}spp-{kind}.png", width, height,
                  [srgb(v) for v in image])
        errors = per_pixel_error(image, reference)
        write_png(f"{outdir}/denoise-{scene}-{spp}spp-{kind}-error.png", width, height,
                  [c for e in errors for c in heat(e)])


if __name__ == "__main__":
    if sys.argv[1] == "table":
        table(sys.argv[2], sys.argv[3], sys.argv[4:])
    else:
        pictures(sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5])
