// GL/osmesa.h after GL/glew.h: GLEW defines the GL/gl.h types and guards,
// then #undefs GLAPI, which osmesa.h needs (as VTK's own OSMesa window does).
#ifndef OSMesaApi_h
#define OSMesaApi_h

#include <GL/glew.h>

#ifndef GLAPI
#define GLAPI extern
#endif
#ifndef GLAPIENTRY
#define GLAPIENTRY
#endif
#include <GL/osmesa.h>

#endif
