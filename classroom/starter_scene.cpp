#include "starter_scene.h"

namespace fl::classroom {

std::string starterScene() {
    return R"x3d(<?xml version="1.0" encoding="UTF-8"?>
<X3D profile='Immersive' version='3.3'>
  <head>
    <component name='FunctionLab' level='1'/>
    <meta name='title' content='Class scene'/>
  </head>
  <Scene>
    <Viewpoint description='Front' position='0 0 6'/>
    <FShape DEF='CLASS'>
      <FGeometry type='implicit' definition='"sphere(0, 0, 0, 1)"'
                 domainMin='-2 -2 -2' domainMax='2 2 2' resolution='48'/>
      <FAppearance>
        <FMaterial type='parametric' definition='"r = 0.8;" "g = 0.8;" "b = 0.85;"'
                   domainMin='-2 -2 -2' domainMax='2 2 2'/>
      </FAppearance>
    </FShape>
  </Scene>
</X3D>
)x3d";
}

} // namespace fl::classroom
