// What adair's 3D view (view.js) uses of three: scripts/vendor-three.sh
// bundles these into one file, assets/view/three.min.js (global THREE).
export {
  AxesHelper, BoxGeometry, BufferAttribute, BufferGeometry, CanvasTexture,
  Color, CylinderGeometry, DirectionalLight, GridHelper, Group,
  HemisphereLight, Line, LineBasicMaterial, LineDashedMaterial, Mesh, MeshBasicMaterial,
  MeshStandardMaterial, PerspectiveCamera, Scene, SphereGeometry, Sprite,
  SpriteMaterial, Vector3, WebGLRenderer, REVISION,
} from "three";
