// A flanged bracket: boxes, a cylinder boss, a through hole and a chamfer.
$fn = 24;
difference() {
  union() {
    cube([40, 24, 6]);
    translate([20, 12, 0]) cylinder(h = 18, r = 8);
    translate([0, 0, 0]) cube([6, 24, 20]);
  }
  translate([20, 12, -1]) cylinder(h = 30, r = 4);
  translate([32, 12, -1]) cylinder(h = 10, r = 2.5);
}
