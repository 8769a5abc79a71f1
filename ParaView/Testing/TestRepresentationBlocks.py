"""pvbatch test of block colours and opacities in the Smooth Silhouette
Surface representation: two coarse spheres grouped in one multiblock dataset,
the first given a red block colour, the second a blue one at opacity 0.5
(display.BlockColors and BlockOpacities, as the GUI's Multiblock Inspector
sets them). Each sphere's centre must show its block's look as Surface draws
it (within 12 of 255 per channel): red, and blue mixed with the white
background through the sphere's two sheets. The red sphere must be drawn smoothed (its
smoothed outline covers more pixels than the chord outline). The checks must
fail for what the representation drew before it honoured the blocks: with the
block colours and opacities cleared, neither centre passes. A second frame
must find both blocks (the opaque one drawn in the opaque pass, the other in
the translucent pass), and a block that loses its colour but keeps its
opacity must go back to the actor's colour, as on Surface. A block colour
wins over colouring by an array, and a colour map's opacity puts the leaves
in the translucent pass, both as on Surface. Settings come from ctest through
the environment."""
import os

from paraview import simple
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

from SilhouetteTestUtils import finish, load_representation_plugin, plain_render_view, setting

load_representation_plugin()

size = [400, 200]
view = plain_render_view(size)
# Looking down z at spheres of radius 0.5 centred at x = -1 and 1: 100 pixels
# per unit, the centres at pixels (100, 100) and (300, 100).
view.CameraPosition = [0.0, 0.0, 10.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 1.0

spheres = [simple.Sphere(Center=[x, 0.0, 0.0], ThetaResolution=8, PhiResolution=6) for x in (-1.0, 1.0)]
group = simple.GroupDatasets(Input=spheres)
display = simple.Show(group, view)
display.ColorArrayName = ["POINTS", ""]
display.Representation = "Smooth Silhouette Surface"


def looks(colours, opacities):
    display.BlockColors = colours
    display.BlockOpacities = opacities


def image():
    simple.Render(view)
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ReadFrontBufferOff()
    grab.Update()
    return grab.GetOutput()


def pixel(picture, x, y):
    return [picture.GetScalarComponentAsDouble(x, y, 0, c) for c in range(3)]


def red_pixels(picture):
    return sum(1 for x in range(size[0] // 2) for y in range(size[1])
        if pixel(picture, x, y)[0] > 60 and max(pixel(picture, x, y)[1:]) < 30)


def red(rgb):
    """The lit red of the first sphere's centre (about 200, 0, 0)."""
    return rgb[0] > 150 and rgb[1] < 30 and rgb[2] < 30


def half_blue(rgb):
    """Blue at opacity 0.5 over white, through the sphere's two sheets (about
    64, 64, 205); opaque blue is about 0, 0, 200, and the actor's colour grey
    or white."""
    return 30 < rgb[0] < 110 and 30 < rgb[1] < 110 and rgb[2] > 180


def near(a, b):
    return max(abs(x - y) for x, y in zip(a, b)) <= 12


failures = []
block_colours = ["/Root/Sphere1", "1", "0", "0", "/Root/Sphere2", "0", "0", "1"]
block_opacities = ["/Root/Sphere2", "0.5"]
looks(block_colours, block_opacities)
# What Surface (VTK's composite mapper) draws for the same looks.
display.Representation = "Surface"
surface = image()
surface_left, surface_right = pixel(surface, 100, 100), pixel(surface, 300, 100)
display.Representation = "Smooth Silhouette Surface"
picture = image()
output_dir = setting("SILHOUETTE_OUTPUT_DIR")
os.makedirs(output_dir, exist_ok=True)
simple.SaveScreenshot(os.path.join(output_dir, "TestRepresentationBlocks.png"), view, ImageResolution=size,
    TransparentBackground=0)
left, right = pixel(picture, 100, 100), pixel(picture, 300, 100)
display.SMProxy.UpdatePropertyInformation()
replaced = display.GetPropertyValue("SilhouetteReplacedTriangles")
print("block looks: the first centre %s, the second %s (Surface: %s, %s); %d triangles replaced"
    % (left, right, surface_left, surface_right, replaced))
if not near(left, surface_left) or not near(right, surface_right):
    failures.append("the centres differ from Surface's by more than 12")
if not red(left):
    failures.append("the first sphere's centre is %s, not its block's red" % left)
if not half_blue(right):
    failures.append("the second sphere's centre is %s, not its block's blue at opacity 0.5" % right)
if replaced <= 0:
    failures.append("nothing was smoothed")

smooth_red = red_pixels(picture)
display.SilhouetteSmoothing = 0
chord_red = red_pixels(image())
display.SilhouetteSmoothing = 1
print("red pixels: %d smoothed, %d with the chord outline" % (smooth_red, chord_red))
if smooth_red <= chord_red:
    failures.append("the red sphere is not drawn smoothed (%d red pixels, chord outline %d)"
        % (smooth_red, chord_red))

# Both leaves persist across passes: the opaque one is drawn in the opaque
# pass, the translucent one in the translucent pass, and a second frame
# finds both (the figures count the two).
image()
display.SMProxy.UpdatePropertyInformation()
blocks = display.GetPropertyValue("SilhouetteRenderedBlocks")
print("blocks counted after a second frame: %d" % blocks)
if blocks != 2:
    failures.append("%d blocks counted after a second frame, not 2" % blocks)

# The second block loses its colour but keeps its opacity: the actor's
# colour again, as Surface draws it.
looks(["/Root/Sphere1", "1", "0", "0"], block_opacities)
display.Representation = "Surface"
surface_right = pixel(image(), 300, 100)
display.Representation = "Smooth Silhouette Surface"
uncoloured_right = pixel(image(), 300, 100)
print("second block without its colour: %s (Surface: %s)" % (uncoloured_right, surface_right))
if not near(uncoloured_right, surface_right):
    failures.append("the second block kept a colour it lost: %s, Surface %s" % (uncoloured_right, surface_right))

# The wrong variant: the actor's look on every block, as before.
looks([], [])
plain = image()
plain_left, plain_right = pixel(plain, 100, 100), pixel(plain, 300, 100)
print("without block looks: the centres %s and %s (must fail both checks)" % (plain_left, plain_right))
if red(plain_left) or half_blue(plain_right):
    failures.append("the checks pass without block looks: they cannot tell")

# A block colour wins over colouring by an array, as on Surface (until
# 2026-12-04 the leaf drew the array's colours).
looks(block_colours, [])
simple.ColorBy(display, ("POINTS", "Normals", "Magnitude"))
display.Representation = "Surface"
surface_left = pixel(image(), 100, 100)
display.Representation = "Smooth Silhouette Surface"
coloured_left = pixel(image(), 100, 100)
print("block colour over colouring by Normals: %s (Surface: %s)" % (coloured_left, surface_left))
if not near(coloured_left, surface_left) or not red(coloured_left):
    failures.append("colouring by an array overrode the block colour: %s, Surface %s"
        % (coloured_left, surface_left))

# Opacity from the colour map (EnableOpacityMapping), at 0.3 everywhere: the
# leaves belong in the translucent pass, as on Surface (until 2026-12-04
# they were drawn in the opaque one, washed out).
looks([], [])
simple.ColorBy(display, ("POINTS", "Normals", "X"))
colours = simple.GetColorTransferFunction("Normals")
colours.EnableOpacityMapping = 1
opacities = simple.GetOpacityTransferFunction("Normals")
opacities.Points = [-1.0, 0.3, 0.5, 0.0, 1.0, 0.3, 0.5, 0.0]
display.Representation = "Surface"
surface = image()
display.Representation = "Smooth Silhouette Surface"
mapped = image()
for x in (100, 300):
    print("opacity from the colour map, centre %d: %s (Surface: %s)"
        % (x, pixel(mapped, x, 100), pixel(surface, x, 100)))
    if not near(pixel(mapped, x, 100), pixel(surface, x, 100)):
        failures.append("with opacity from the colour map the centre %d is %s, Surface %s"
            % (x, pixel(mapped, x, 100), pixel(surface, x, 100)))
colours.EnableOpacityMapping = 0

finish(failures)
