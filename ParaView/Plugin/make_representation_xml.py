# Writes ParaView/Plugin/SilhouetteRepresentation.xml (the four Extension
# blocks repeat one property list): edit the list here, then
#   python3 ParaView/Plugin/make_representation_xml.py ParaView/Plugin/SilhouetteRepresentation.xml
props = [
  # name, kind, default, label, doc, extra, advanced
  ("SilhouetteSmoothing", "bool", "1", "Smooth Silhouettes",
   "Smooth the silhouette for the view at every render (off: the coarse mesh as it is, with the smoothing's shading normals).", "", False),
  ("SilhouetteTolerance", "double", "0.5", "Tolerance",
   "Largest distance in pixels between a sampled curve and the smooth curve.",
   '<DoubleRangeDomain name="range" min="0.001" max="10"/>', False),
  ("SilhouetteMinimumSamples", "int", "2", "Minimum Samples",
   "Fewest points per curve segment, both ends counted.", '<IntRangeDomain name="range" min="2" max="65536"/>', True),
  ("SilhouetteMaximumSamples", "int", "256", "Maximum Samples",
   "Most points per curve segment, both ends counted.", '<IntRangeDomain name="range" min="2" max="65536"/>', True),
  ("SilhouetteNewPointBudget", "double", "8", "New Point Budget",
   "The most points one frame's sampling adds, as a multiple of the input's points (at least 100,000); a frame that would need more samples each segment less.",
   '<DoubleRangeDomain name="range" min="1" max="1000000"/>', True),
  ("SilhouetteSamplingRule", "int", "0", "Sampling Rule",
   "How the sample count is chosen; equation 8 is the paper's, kept for comparison.",
   '<EnumerationDomain name="enum"><Entry value="0" text="Second difference"/><Entry value="1" text="Wang equation 8"/></EnumerationDomain>', True),
  ("SilhouettePerturbVertices", "bool", "1", "Perturb Vertices",
   "Lower the vertices around concave silhouette segments (paper III-E).", "", False),
  ("SilhouetteFoldPrevention", "bool", "1", "Fold Prevention",
   "Never fold: silhouette triangles whose new triangles turn over or cut through others are re-meshed along the chord, then on their straight edges; lowered vertices that fold stay in place.", "", False),
  ("SilhouetteReuseFoldFallbacks", "bool", "1", "Reuse Fold Fallbacks",
   "A triangle that folds again goes at once to the fallback it needed in the render before, instead of one re-meshing round at a time (coarse meshes render faster while the camera moves; a triangle whose curve no longer folds is drawn curved).", "", True),
  ("SilhouetteKeepApexesPointed", "bool", "1", "Keep Apexes Pointed",
   "Keep cones pointed: at a vertex where the surface comes to a point, the silhouette stays on the mesh's edges (its one normal would round the cone into a dome).", "", True),
  ("SilhouetteSkipSubpixelSmoothing", "bool", "1", "Skip Sub-pixel Smoothing",
   "Leave as they are the stretches of silhouette whose smoothing would move the image by less than the tolerance (a fine mesh's: a frame then costs little more than finding its silhouette).", "", True),
  ("SilhouetteFeatureLines", "bool", "1", "Feature Lines",
   "Line cells along triangle edges mark feature edges (creases).", "", True),
  ("SilhouetteFeatureEdgeDetection", "bool", "0", "Feature Edge Detection",
   "Also take as feature edges the edges sharper than Feature Angle.", "", False),
  ("SilhouetteFeatureAngle", "double", "30", "Feature Angle",
   "Degrees between face normals above which an edge is a feature edge.", '<DoubleRangeDomain name="range" min="0" max="180"/>', False),
  ("SilhouetteFlatCreaseDetection", "bool", "1", "Flat Crease Detection",
   "Creases between flat faces (boxes, CAD parts): edges sharper than Flat Crease Angle whose triangles each lie flat against another neighbour, and the outlines of flat faces that sharp all round (a cone's base).", "", True),
  ("SilhouetteFlatCreaseAngle", "double", "65", "Flat Crease Angle",
   "Degrees above which an edge between flat faces is a crease.", '<DoubleRangeDomain name="range" min="0" max="180"/>', True),
  ("SilhouetteNormalSeamFeatures", "bool", "1", "Normal Seam Features",
   "Points at one position with different normals mark a crease (hard edges of asset files).", "", True),
  ("SilhouetteWeldCoincidentPoints", "bool", "1", "Weld Coincident Points",
   "Points at one position are one surface vertex (texture seams, triangle soups); each triangle keeps its own points.", "", True),
  ("SilhouetteWeldTolerance", "double", "0", "Weld Tolerance",
   "Points within this distance are welded (0: equal coordinates only).", '<DoubleRangeDomain name="range" min="0"/>', True),
  ("SilhouetteConsistentOrientation", "bool", "1", "Consistent Orientation",
   "Orient the triangles consistently per connected part (closed parts outward) before computing normals and visibility.", "", True),
  ("SilhouetteNormalEstimation", "int", "1", "Normal Estimation",
   "How the shading normals the input does not give are estimated.",
   '<EnumerationDomain name="enum"><Entry value="0" text="Angle weighted"/><Entry value="1" text="Area weighted"/><Entry value="2" text="Max weights"/><Entry value="3" text="Quadric fit"/></EnumerationDomain>', False),
  ("SilhouetteVisibilityMethod", "int", "0", "Visibility Method",
   "How the vertices facing the viewer are found (same result; hierarchical pays on large meshes).",
   '<EnumerationDomain name="enum"><Entry value="0" text="Per vertex"/><Entry value="1" text="Hierarchical"/></EnumerationDomain>', True),
  ("SilhouetteSmoothLOD", "bool", "1", "Smooth LOD",
   "While interacting with large data ParaView draws a decimated copy (LOD); smooth its silhouette too. Off: the decimated copy is drawn as it is (slightly cheaper interaction, a coarse outline while the camera moves).", "", True),
]
infos = [
  ("SilhouetteReplacedTriangles", "The triangles the last render on the first process replaced with smoothed ones (this and the following: figures of the first process)."),
  ("SilhouettePatchTriangles", "The triangles drawn in their place."),
  ("SilhouetteRenderedBlocks", "The blocks (leaves) the last render drew."),
  ("SilhouetteDrawnCells", "The cells of those blocks the last render drew."),
  ("SilhouetteSkippedGhostCells", "Their ghost cells (vtkGhostType: duplicate or hidden) the last render left out."),
  ("SilhouetteSmoothingRuns", "How many times the blocks were smoothed for a view, over the representation's life: new values on a still mesh (a time series of them) smooth nothing again."),
  ("SilhouetteNormalsPerPiece", "1 when the data runs on several processes without point normals: each piece's normals are its own, and the pieces' seams show as lines (apply Generate Surface Normals first)."),
]

def prop_xml(p):
    name, kind, default, label, doc, extra, adv = p
    tag = "DoubleVectorProperty" if kind == "double" else "IntVectorProperty"
    if kind == "bool":
        extra = '<BooleanDomain name="bool"/>'
    command = "Set" + name
    a = ' panel_visibility="advanced"' if adv else ""
    return ('      <%s name="%s" label="%s" command="%s"\n        number_of_elements="1" default_values="%s"%s>\n'
            '        %s\n        <Documentation>%s</Documentation>\n      </%s>\n') % (
        tag, name, label, command, default, a, extra, doc, tag)

def info_xml(i):
    name, doc = i
    return ('      <IntVectorProperty name="%s" command="Get%s" information_only="1"\n'
            '        number_of_elements="1" default_values="0" panel_visibility="never">\n'
            '        <SimpleIntInformationHelper/>\n        <Documentation>%s</Documentation>\n'
            '      </IntVectorProperty>\n') % (name, name, doc)

exposed = "".join('            <Property name="%s"/>\n' % p[0] for p in props)
exposed_info = "".join('          <Property name="%s"/>\n' % i[0] for i in infos)

def extension(base):
    return '''
    <Extension name="%s">
      <Documentation>Adds Smooth Silhouette Surface to the Representation list.</Documentation>
      <RepresentationType subproxy="SmoothSilhouetteSurfaceRepresentation"
        text="Smooth Silhouette Surface" subtype="Surface"/>
      <SubProxy>
        <Proxy name="SmoothSilhouetteSurfaceRepresentation"
          proxygroup="representations" proxyname="SmoothSilhouetteSurfaceRepresentation"/>
        <ShareProperties subproxy="SurfaceRepresentation">
          <Exception name="Input"/>
          <Exception name="Visibility"/>
          <Exception name="Representation"/>
        </ShareProperties>
        <ExposedProperties>
          <PropertyGroup label="Silhouette Smoothing">
%s            <Hints>
              <PropertyWidgetDecorator type="GenericDecorator" mode="visibility"
                property="Representation" value="Smooth Silhouette Surface"/>
            </Hints>
          </PropertyGroup>
%s        </ExposedProperties>
      </SubProxy>
    </Extension>
''' % (base, exposed, exposed_info)

out = '''<ServerManagerConfiguration>
  <!-- The Smooth Silhouette Surface representation: a subtype of Surface
       drawn through vtkSilhouetteCompositeMapper. The four Extension blocks
       (one per representation that offers Surface, as Surface LIC has) list
       the same properties; made by make_representation_xml.py, which holds
       the one list. -->
  <ProxyGroup name="representations">
    <RepresentationProxy name="SmoothSilhouetteSurfaceRepresentation"
      class="vtkSilhouetteSmoothingRepresentation"
      processes="client|renderserver|dataserver"
      base_proxygroup="representations"
      base_proxyname="SurfaceRepresentation">
      <Documentation
        short_help="Surface with its silhouette smoothed for the view at render time.">
        Draws the surface as Surface does, with the silhouette of a coarse
        triangle mesh smoothed for the view's camera and size at every render
        (view-dependent silhouette smoothing, Wang et al. 2008): only the
        triangles along the silhouette are re-meshed, every camera move is
        smoothed again, nothing needs to be copied from the view. Every rank
        smooths its own piece; ghost cells are not drawn.
      </Documentation>
%s%s    </RepresentationProxy>
%s%s%s%s  </ProxyGroup>
</ServerManagerConfiguration>
''' % ("".join(prop_xml(p) for p in props), "".join(info_xml(i) for i in infos),
       extension("GeometryRepresentation"), extension("UnstructuredGridRepresentation"),
       extension("StructuredGridRepresentation"), extension("UniformGridRepresentation"))
import sys
open(sys.argv[1], "w").write(out)
