#!/bin/sh
# Installs everything Toonface needs to build, test and run, from Debian 12 packages only.
# The single list of the project's dependencies: the README and CI both call this script.
set -eu
if [ "$(id -u)" -ne 0 ]; then
  exec sudo "$0" "$@"
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends \
  build-essential cmake ninja-build pkg-config git clang-format clang libclang-rt-14-dev \
  qt6-base-dev qt6-base-dev-tools qt6-svg-dev qt6-multimedia-dev qt6-tools-dev qt6-tools-dev-tools \
  qt6-l10n-tools qt6-translations-l10n qt6-qpa-plugins libqt6svg6 libgl-dev \
  libopencv-dev libdlib-dev libdlib-data libblas-dev liblapack-dev \
  libespeak-ng-dev espeak-ng espeak-ng-data libbz2-dev \
  unicode-data rime-data-terra-pinyin rime-data-pinyin-simp \
  libavcodec-dev libavformat-dev libavutil-dev libswresample-dev libswscale-dev \
  gstreamer1.0-plugins-good gstreamer1.0-libav \
  python-matplotlib-data python3-skimage fonts-wqy-microhei fonts-dejavu-core \
  xvfb xauth chromium sox pulseaudio pulseaudio-utils \
  zlib1g-dev epubcheck libwebp-dev
