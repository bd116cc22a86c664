#!/bin/sh
# The main job of `make run`: renders the default synthetic Mars scene with its ground truth,
# runs one navigation cycle on the rendered pair, then the same cycle at 128 x 128 as OCCAM
# processes on the emulated PC transputer card and on the rover's onboard computer, the paper's
# timings from the model, a campaign of module hangs and power losses under the overswitch, and
# one 80 m traverse on a rock-free site (craters only).
set -eu
marsokhod="$1"
out="$2"
world_dir="$out/world-seed3"
nav_dir="$out/nav-seed3"
emulate_dir="$out/emulate-pc-card-seed3"
onboard_dir="$out/emulate-onboard-seed3"
reproduce_dir="$out/reproduce"
campaign_dir="$out/campaign-hang-power"
traverse_dir="$out/traverse-seed1"

"$marsokhod" world --seed 3 --size 256 --out "$world_dir"
echo
"$marsokhod" nav "$world_dir/left.pgm" "$world_dir/right.pgm" --scene "$world_dir/scene.json" \
  --out "$nav_dir"
echo
"$marsokhod" emulate --platform pc-card --seed 3 --size 128 --out "$emulate_dir" \
  --trace "$emulate_dir/trace.json"
echo
"$marsokhod" emulate --platform onboard --seed 3 --size 128 --out "$onboard_dir" \
  --trace "$onboard_dir/trace.json"
echo
"$marsokhod" reproduce --out "$reproduce_dir"
echo
"$marsokhod" campaign campaigns/hang-power.toml --jobs 2 --out "$campaign_dir"
echo
"$marsokhod" traverse --seed 1 --rocks 0 --out "$traverse_dir"
echo
"$marsokhod" report "$world_dir" "$nav_dir" "$emulate_dir" "$onboard_dir" "$reproduce_dir" \
  "$campaign_dir" "$traverse_dir" --title "marsokhod: make run" --out "$out/report.html"
echo
echo "make run: results are in $world_dir, $nav_dir, $emulate_dir, $onboard_dir, $reproduce_dir"
echo "$campaign_dir and $traverse_dir"
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
echo "  $emulate_dir:"
echo "    the same products as nav, from the emulated cycle at 128 x 128 on the PC card"
echo "    trace.json                        the cycle in Perfetto (ui.perfetto.dev): CPUs, stages, links, memory"
echo "  $onboard_dir:"
echo "    the same again on the onboard computer's two 256 KB modules (terrain and zones"
echo "    worked out again where the memory cannot keep them), with its trace.json"
echo "  $reproduce_dir:"
echo "    reproduce.md / .json / .png       the paper's 8 s, 10 s and 1.3 min beside the model's"
echo "    sweep.png / .csv / .json          the onboard cycle against each module's memory"
echo "  $campaign_dir:"
echo "    summary.md / .json                1,000 module hangs and power losses onboard: outcomes,"
echo "                                      detection, failover to a spare, the unsafe rate"
echo "    outcomes.png, latency.png         outcomes by fault kind, detection latency"
echo "    runs.jsonl                        one record per run; campaign --replay K repeats one"
echo "  $traverse_dir:"
echo "    map.png                           an 80 m course driven cycle after cycle, from above"
echo "    traverse.json, cycles.jsonl       the outcome, distances, stops, and each cycle"
echo
echo "All of it in one page: $out/report.html (open it in a browser; everything is inside it)"
