// The examples: documents made with Sketchmesh, kept beside the page as their sessions
// (web/examples/, listed in index.json with a caption for each step), so that a visitor can
// open one, or watch it made again step by step (crates/app/src/making.rs).

let listed = null;

// The examples as index.json lists them: `{name, title, description, session, thumbnail,
// captions}`. Read once; a failed read is tried again the next time.
function all() {
  listed ??= fetch("examples/index.json")
    .then((response) => {
      if (!response.ok) throw new Error(`the list of examples did not load (${response.status})`);
      return response.json();
    })
    .then((index) => index.examples)
    .catch((error) => {
      listed = null;
      throw error;
    });
  return listed;
}

// `{name, title, description, thumbnail}` of each example, for the page API and the panel.
export async function list() {
  return (await all()).map(({ name, title, description, thumbnail }) => ({ name, title, description, thumbnail }));
}

// Example `name` with its session's text; an Error naming the examples for an unknown name.
export async function load(name) {
  const examples = await all();
  const example = examples.find((e) => e.name === name);
  if (example == null) {
    const names = examples.map((e) => `"${e.name}"`).join(", ");
    throw new Error(`There is no example named "${name}". The examples are ${names}.`);
  }
  const response = await fetch(`examples/${example.session}`);
  if (!response.ok) throw new Error(`The example "${example.title}" did not load (${response.status}).`);
  return { ...example, text: await response.text() };
}
