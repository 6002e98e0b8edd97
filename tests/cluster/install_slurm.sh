#!/usr/bin/env bash
# Installs what tests/cluster/slurm_cluster.sh needs on Debian 12: slurm-wlm (slurmctld, slurmd,
# and slurm-client: sbatch, sinfo, squeue, scontrol, scancel) and munge.
# Idempotent: when every package is installed it installs nothing and does not run apt-get update.
# Installing does not start any daemon here (no systemd); the test starts its own.
# Needs root, or sudo.
set -euo pipefail

packages=(slurm-wlm slurmctld slurmd slurm-client munge)

missing=()
for pkg in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done

if ((${#missing[@]} == 0)); then
  echo "install_slurm: ${packages[*]} already installed"
else
  echo "install_slurm: installing missing Debian packages: ${missing[*]}"
  sudo=()
  if ((EUID != 0)); then
    command -v sudo >/dev/null || {
      echo "install_slurm: not root and no sudo; as root: apt-get install -y ${missing[*]}" >&2
      exit 1
    }
    sudo=(sudo)
  fi
  "${sudo[@]}" apt-get update -q
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# What the test runs must now be there (slurmctld, slurmd and munged live in /usr/sbin).
for cmd in slurmctld slurmd sbatch sinfo squeue scontrol scancel munged munge unmunge; do
  PATH="$PATH:/usr/sbin:/sbin" command -v "$cmd" >/dev/null || {
    echo "install_slurm: $cmd not found after installing ${packages[*]}" >&2
    exit 1
  }
done
echo "install_slurm: $(dpkg-query -W -f='${Package} ${Version}  ' slurm-wlm munge)"
