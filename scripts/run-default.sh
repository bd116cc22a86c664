#!/bin/sh
# The main job of `make run`: renders the default synthetic Mars scene with its ground truth,
# then runs one navigation cycle on the rendered pair.
set -eu
marsokhod="$1"
out="$2"
world_dir="$out/world-seed3"
nav_dir="$out/nav-seed3"

"$marsokhod" world --seed 3 --size 256 --out "$world_dir"
echo
"$marsokhod" nav "$world_dir/left.pgm" "$world_dir/right.pgm" --scene "$world_dir/scene.json" \
  --out "$nav_dir"
echo
echo "make run: results are in $world_dir and $nav_dir"
echo "  $world_dir:"
echo "    left.png / right.png              the rendered stereo pair"
echo "    gt_disparity.png, gt_range.png    ground truth, false colour with a legend"
echo "    gt_elevation.png, gt_obstacles.png"
echo "    scene.json                        rig, pose, seed and generator settings"
echo "  $nav_dir:"
echo "    disparity.png, elevation.png      the matched disparity and the elevation map"
echo "    zones.png                         prohibited white, rover margin grey, traversable black"
echo "    path_overlay.png                  the safest path over the left image"
echo "    path.json                         path, start/fracture/target distances, drive commands"
