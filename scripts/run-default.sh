#!/bin/sh
# The main job of `make run`: renders the default synthetic Mars scene with its ground truth.
set -eu
marsokhod="$1"
out="$2"
world_dir="$out/world-seed1"

"$marsokhod" world --seed 1 --size 256 --out "$world_dir"
echo
echo "make run: results are in $world_dir"
echo "  left.png / right.png              the rendered stereo pair"
echo "  gt_disparity.png, gt_range.png    ground truth, false colour with a legend"
echo "  gt_elevation.png, gt_obstacles.png"
echo "  scene.json                        rig, pose, seed and generator settings"
