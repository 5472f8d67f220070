//! The server driven in process, as an editor drives it: initialize, open, change,
//! and every request, with the notifications it sends back.

use futures::StreamExt;
use serde_json::{Value, json};
use tower::{Service, ServiceExt};
use tower_lsp_server::jsonrpc::Request;

const URI: &str = "file:///work/scene.walls";

struct Client {
    service: tower_lsp_server::LspService<walls_lsp::Backend>,
    socket: tower_lsp_server::ClientSocket,
    next_id: i64,
}

impl Client {
    async fn start(init: Value) -> Self {
        Client::start_in(init, None).await
    }

    /// Starts the server with the workspace folder at `folder`, if one is given.
    async fn start_in(init: Value, folder: Option<&str>) -> Self {
        let (service, socket) = walls_lsp::service();
        let mut c = Client {
            service,
            socket,
            next_id: 1,
        };
        let folders = folder.map(|uri| json!([{"uri": uri, "name": "project"}]));
        let caps = c
            .request(
                "initialize",
                json!({"capabilities": {}, "initializationOptions": init, "workspaceFolders": folders}),
            )
            .await;
        assert_eq!(caps["serverInfo"]["name"], "walls-lsp");
        c.notify("initialized", json!({})).await;
        c
    }

    async fn request(&mut self, method: &'static str, params: Value) -> Value {
        let id = self.next_id;
        self.next_id += 1;
        let req = Request::build(method).params(params).id(id).finish();
        let response = self
            .service
            .ready()
            .await
            .unwrap()
            .call(req)
            .await
            .unwrap()
            .unwrap();
        let (_, result) = response.into_parts();
        result.expect("request succeeds")
    }

    async fn notify(&mut self, method: &'static str, params: Value) {
        let req = Request::build(method).params(params).finish();
        self.service.ready().await.unwrap().call(req).await.unwrap();
    }

    /// The parameters of the next notification `method` from the server.
    async fn notification(&mut self, method: &str) -> Value {
        loop {
            let message = self
                .socket
                .next()
                .await
                .unwrap_or_else(|| panic!("the server sends {method}"));
            if message.method() == method {
                return message.params().cloned().unwrap();
            }
        }
    }

    /// The next `publishDiagnostics` notification.
    async fn diagnostics(&mut self) -> Value {
        self.notification("textDocument/publishDiagnostics").await
    }

    /// The text of the next `window/showMessage` notification.
    async fn message(&mut self) -> String {
        let params = self.notification("window/showMessage").await;
        params["message"].as_str().unwrap().into()
    }

    async fn open(&mut self, text: &str) -> Value {
        self.open_at(URI, text).await
    }

    /// Opens `text` at `uri`; its diagnostics.
    async fn open_at(&mut self, uri: &str, text: &str) -> Value {
        self.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": uri, "languageId": "walls", "version": 1, "text": text}}),
        )
        .await;
        self.diagnostics().await
    }

    /// Replaces the text of the document at `uri` with `text` at `version`; its
    /// diagnostics.
    async fn change(&mut self, uri: &str, version: i32, text: &str) -> Value {
        self.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": uri, "version": version}, "contentChanges": [{"text": text}]}),
        )
        .await;
        self.diagnostics().await
    }

    /// The code actions of the document at `uri` for the range from `start` to `end`
    /// (line, character).
    async fn actions(&mut self, uri: &str, start: (u32, u32), end: (u32, u32)) -> Value {
        let at = |(line, character): (u32, u32)| json!({"line": line, "character": character});
        self.request(
            "textDocument/codeAction",
            json!({"textDocument": {"uri": uri}, "range": {"start": at(start), "end": at(end)}, "context": {"diagnostics": []}}),
        )
        .await
    }

    /// The edits of `textDocument/formatting` for the document at `uri`.
    async fn format(&mut self, uri: &str) -> Value {
        self.request(
            "textDocument/formatting",
            json!({"textDocument": {"uri": uri}, "options": {"tabSize": 2, "insertSpaces": true}}),
        )
        .await
    }
}

/// The titles of code actions.
fn titles(actions: &Value) -> Vec<&str> {
    actions
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a["title"].as_str().unwrap())
        .collect()
}

/// The codes of published diagnostics (`-` for one without a code).
fn codes(published: &Value) -> Vec<String> {
    published["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["code"].as_str().unwrap_or("-").to_string())
        .collect()
}

#[tokio::test]
async fn diagnostics_follow_versions_and_settings() {
    let mut c = Client::start(json!({})).await;
    let published = c.open("wall type disk\n  raduis 0.5\n").await;
    assert_eq!(published["version"], 1);
    assert_eq!(codes(&published), ["S101"]);
    let d = &published["diagnostics"][0];
    assert_eq!(
        d["range"],
        json!({"start": {"line": 1, "character": 2}, "end": {"line": 1, "character": 8}})
    );
    assert_eq!(d["source"], "walls");

    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": URI, "version": 2}, "contentChanges": [{"text": "wall type triangle\n"}]}),
    )
    .await;
    let published = c.diagnostics().await;
    assert_eq!(published["version"], 2);
    assert!(codes(&published).is_empty());

    // An older version arriving late changes nothing.
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": URI, "version": 1}, "contentChanges": [{"text": "raduis\n"}]}),
    )
    .await;
    // The mode comes from the settings: HSDEM refuses triangles.
    c.notify(
        "workspace/didChangeConfiguration",
        json!({"settings": {"walls": {"mode": "hsdem"}}}),
    )
    .await;
    let published = c.diagnostics().await;
    assert_eq!(published["version"], 2);
    assert_eq!(codes(&published), ["M003", "M003", "M001"]);
}

#[tokio::test]
async fn hover_formatting_actions_symbols_folding() {
    let mut c = Client::start(json!({"mode": "ssdem"})).await;
    let text = "lengthunit 2\ndefaults radius 0.25\nWALL TYPE disk\n  radius,0.5\n  color 3\nwall type plane\n  radius 1\n";
    let published = c.open(text).await;
    assert_eq!(codes(&published), ["C207", "C201"]);

    let hover = c
        .request(
            "textDocument/hover",
            json!({"textDocument": {"uri": URI}, "position": {"line": 3, "character": 4}}),
        )
        .await;
    let shown = hover["contents"]["value"].as_str().unwrap();
    assert!(
        shown.starts_with("**radius** — a number, length (× lengthunit); default 1"),
        "{shown}"
    );
    assert!(
        shown.contains("In wall 0: **1** (pkdgrav units), from this token."),
        "{shown}"
    );

    let edits = c.format(URI).await;
    assert_eq!(
        edits[0]["newText"],
        "lengthunit 2\ndefaults radius 0.25\n\nwall type disk\n  radius 0.5\n  color 3\n\nwall type plane\n  radius 1\n"
    );

    let actions = c.actions(URI, (6, 0), (6, 10)).await;
    assert_eq!(
        titles(&actions),
        [
            "remove `radius`, which has no effect (C201)",
            "Fix all safe problems (2)"
        ]
    );
    let fix_all = &actions[1]["edit"]["changes"][URI][0]["newText"];
    assert_eq!(
        fix_all,
        "lengthunit 2\ndefaults\nWALL TYPE disk\n  radius,0.5\n  color 3\nwall type plane\n"
    );

    let symbols = c
        .request(
            "textDocument/documentSymbol",
            json!({"textDocument": {"uri": URI}}),
        )
        .await;
    let names: Vec<&str> = symbols
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        ["lengthunit", "defaults", "wall 0: disk", "wall 1: plane"]
    );
    assert_eq!(symbols[2]["children"][0]["detail"], "disk");
    assert_eq!(symbols[2]["children"][1]["name"], "radius");
    assert_eq!(symbols[2]["children"][1]["detail"], "0.5");

    let folds = c
        .request(
            "textDocument/foldingRange",
            json!({"textDocument": {"uri": URI}}),
        )
        .await;
    assert_eq!(
        folds,
        json!([{"startLine": 2, "endLine": 4, "kind": "region"}, {"startLine": 5, "endLine": 6, "kind": "region"}])
    );
}

#[tokio::test]
async fn completion_tokens_hints_definition() {
    let mut c = Client::start(json!({})).await;
    let text =
        "lengthunit 2\ndefaults color 3\nwall type disk\n  radius 0.5 # r\n  k_n 7\n  type \n";
    c.open(text).await;
    let at = |line: u32, character: u32| json!({"textDocument": {"uri": URI}, "position": {"line": line, "character": character}});

    let types = c.request("textDocument/completion", at(5, 7)).await;
    let labels: Vec<&str> = types
        .as_array()
        .unwrap()
        .iter()
        .map(|i| i["label"].as_str().unwrap())
        .collect();
    assert_eq!(
        labels,
        [
            "plane",
            "triangle",
            "rectangle",
            "disk",
            "cylinder-infinite",
            "cylinder-finite",
            "shell",
            "disc"
        ]
    );

    let keywords = c.request("textDocument/completion", at(4, 7)).await;
    let items = keywords.as_array().unwrap();
    let item = |name: &str| items.iter().find(|i| i["label"] == name).unwrap().clone();
    assert!(
        item("hole-radius")["sortText"].as_str().unwrap()
            < item("vertex1")["sortText"].as_str().unwrap()
    );
    assert_eq!(item("origin")["insertText"], "origin ${1:0} ${2:0} ${3:0}");
    assert_eq!(
        item("type")["insertText"],
        "type ${1|plane,triangle,rectangle,disk,cylinder-infinite,cylinder-finite,shell|}"
    );
    let in_comment = c.request("textDocument/completion", at(3, 15)).await;
    assert_eq!(in_comment, json!([]));

    let tokens = c
        .request(
            "textDocument/semanticTokens/full",
            json!({"textDocument": {"uri": URI}}),
        )
        .await;
    let data = tokens["data"].as_array().unwrap();
    // lengthunit (keyword), 2 (number): [line, start, length, type, modifiers] deltas.
    assert_eq!(
        data[..10],
        [
            json!(0),
            json!(0),
            json!(10),
            json!(0),
            json!(0),
            json!(0),
            json!(11),
            json!(1),
            json!(3),
            json!(0)
        ]
    );
    let ranged = c
        .request("textDocument/semanticTokens/range", json!({"textDocument": {"uri": URI}, "range": {"start": {"line": 3, "character": 0}, "end": {"line": 3, "character": 99}}}))
        .await;
    assert_eq!(
        ranged["data"].as_array().unwrap().len(),
        3 * 5,
        "radius, 0.5 and the comment"
    );

    let hints = c
        .request("textDocument/inlayHint", json!({"textDocument": {"uri": URI}, "range": {"start": {"line": 0, "character": 0}, "end": {"line": 9, "character": 0}}}))
        .await;
    let labels: Vec<&str> = hints
        .as_array()
        .unwrap()
        .iter()
        .map(|h| h["label"].as_str().unwrap())
        .collect();
    assert_eq!(
        labels,
        ["inherits color 3", "= 1 in pkdgrav units", "k_t = 2"]
    );
    assert_eq!(hints[1]["position"], json!({"line": 3, "character": 12}));

    let from_wall = c.request("textDocument/definition", at(2, 1)).await;
    assert_eq!(
        from_wall,
        json!([{"uri": URI, "range": {"start": {"line": 1, "character": 15}, "end": {"line": 1, "character": 16}}}])
    );
    let from_radius = c.request("textDocument/definition", at(3, 3)).await;
    assert_eq!(
        from_radius[0]["range"]["start"],
        json!({"line": 3, "character": 9})
    );
}

#[tokio::test]
async fn a_whole_session_snapshot() {
    let mut c = Client::start(json!({})).await;
    let text =
        "lengthunit 2\ndefaults color 3\nwall type disk # d\n  radius 0.5\n  origin 1 2\n3\n";
    let published = c.open(text).await;
    let doc = json!({"textDocument": {"uri": URI}});
    let at = |line: u32, character: u32| json!({"textDocument": {"uri": URI}, "position": {"line": line, "character": character}});
    let all_lines = json!({"textDocument": {"uri": URI}, "range": {"start": {"line": 0, "character": 0}, "end": {"line": 9, "character": 0}}});
    let session = json!({
        "diagnostics": published,
        "hover": c.request("textDocument/hover", at(3, 3)).await,
        "symbols": c.request("textDocument/documentSymbol", doc.clone()).await,
        "folding": c.request("textDocument/foldingRange", doc.clone()).await,
        "formatting": c.format(URI).await,
        "actions": c.request("textDocument/codeAction", json!({"textDocument": {"uri": URI}, "range": {"start": {"line": 4, "character": 0}, "end": {"line": 5, "character": 1}}, "context": {"diagnostics": []}})).await,
        "hints": c.request("textDocument/inlayHint", all_lines.clone()).await,
        "definition": c.request("textDocument/definition", at(2, 1)).await,
    });
    insta::assert_json_snapshot!(session);
}

#[tokio::test]
async fn formatting_reads_the_project_configuration() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join(".walls-fmt.toml"), "indent_width = 4\n").unwrap();
    let path = dir.path().join("my scene.walls");
    let uri = format!("file://{}", path.display()).replace(' ', "%20");
    let mut c = Client::start(json!({})).await;
    c.open_at(&uri, "wall type disk radius 1\n").await;
    let edits = c.format(&uri).await;
    assert_eq!(edits[0]["newText"], "wall type disk\n    radius 1\n");
    // The [format] table of a nearer walls.toml, as walls-fmt reads it.
    std::fs::create_dir(dir.path().join("sub")).unwrap();
    std::fs::write(
        dir.path().join("sub/walls.toml"),
        "[format]\nindent-width = 3\n",
    )
    .unwrap();
    let uri = format!("file://{}/sub/b.walls", dir.path().display()).replace(' ', "%20");
    c.open_at(&uri, "wall type disk radius 1\n").await;
    let edits = c.format(&uri).await;
    assert_eq!(edits[0]["newText"], "wall type disk\n   radius 1\n");
}

#[tokio::test]
async fn hovers_say_where_values_really_come_from() {
    let mut c = Client::start(json!({})).await;
    let text = "wall type plane\n  k_t 1\n  k_n 7\n  origin 1 1 1\n  origin 2 2 2\n  transparency 50\nlengthunit 2\norigin 1 1 1\n";
    c.open(text).await;
    let mut hover = async |line: u32, character: u32| -> Value {
        c.request("textDocument/hover", json!({"textDocument": {"uri": URI}, "position": {"line": line, "character": character}}))
            .await
    };
    let note = |h: &Value| {
        h["contents"]["value"]
            .as_str()
            .unwrap()
            .rsplit("\n\n")
            .next()
            .unwrap()
            .to_string()
    };
    assert_eq!(
        note(&hover(1, 3).await),
        "In wall 0: **2** (pkdgrav units), from the `k_n` on line 3 (2/7 of it)."
    );
    assert_eq!(
        note(&hover(3, 3).await),
        "In wall 0: **2 2 2** (pkdgrav units), from the `origin` on line 5, which wins."
    );
    assert_eq!(
        note(&hover(5, 3).await),
        "In wall 0: **0.5** (pkdgrav units), from this token. Written as 50, a percentage."
    );
    // Outside any block: the documentation only.
    assert!(note(&hover(7, 1).await).starts_with("A point of the wall"));
    // Past the end of a line, or of the file: nothing.
    assert_eq!(hover(0, 40).await, Value::Null);
    assert_eq!(hover(40, 0).await, Value::Null);
}

#[tokio::test]
async fn a_lone_carriage_return_ends_a_line() {
    let mut c = Client::start(json!({})).await;
    let published = c.open("wall type plane\r  raduis 1\n").await;
    // The carriage return itself (S006), then the misspelt keyword on the next line.
    assert_eq!(
        published["diagnostics"][0]["range"],
        json!({"start": {"line": 0, "character": 15}, "end": {"line": 1, "character": 0}})
    );
    assert_eq!(
        published["diagnostics"][1]["range"],
        json!({"start": {"line": 1, "character": 2}, "end": {"line": 1, "character": 8}})
    );
}

#[tokio::test]
async fn explains_codes_as_walls_lint_does() {
    let mut c = Client::start(json!({})).await;
    let by_id = c.request("walls/explain", json!({"query": "s101"})).await;
    let text = by_id.as_str().unwrap();
    assert!(text.starts_with("S101 (unknown-word): "), "{text}");
    assert_eq!(
        c.request("walls/explain", json!({"query": "unknown-word"}))
            .await,
        by_id
    );
    let keyword = c.request("walls/explain", json!({"query": "radius"})).await;
    assert!(keyword.as_str().unwrap().starts_with("**radius**"));
    assert_eq!(
        c.request("walls/explain", json!({"query": "nothing"}))
            .await,
        Value::Null
    );
}

#[tokio::test]
async fn bad_settings_are_named_and_the_rest_applies() {
    let mut c = Client::start(json!({"mode": "fast", "maxWalls": -3, "maxwalls": 30})).await;
    assert_eq!(
        c.message().await,
        "walls: setting `maxWalls` is -3, not a whole number of at least 1: keeping 20; \
         unknown setting `maxwalls` (= 30) ignored; the settings are `mode` and `maxWalls`; \
         setting `mode` is \"fast\", not \"ssdem\" or \"hsdem\": keeping \"ssdem\"."
    );
    // With no document open, so that the test reads each notification as it comes.
    c.notify(
        "workspace/didChangeConfiguration",
        json!({"settings": {"walls": {"mode": "hsdem", "maxWalls": "9", "server": {"path": "walls-lsp"}}}}),
    )
    .await;
    assert_eq!(
        c.message().await,
        "walls: setting `maxWalls` is \"9\", not a whole number of at least 1: keeping 20."
    );
    // The good setting applies: hsdem wants each wall's `k_n`.
    let published = c.open("wall type disk radius 1\n").await;
    assert!(
        codes(&published).iter().any(|c| c.starts_with('M')),
        "{published}"
    );
}

#[tokio::test]
async fn a_broken_format_configuration_is_named_and_the_defaults_format() {
    let dir = tempfile::tempdir().unwrap();
    let config = dir.path().join(".walls-fmt.toml");
    std::fs::write(&config, "indent_width = 4\nindent = 4\n").unwrap();
    let uri = format!("file://{}/scene.walls", dir.path().display());
    let mut c = Client::start(json!({})).await;
    c.open_at(&uri, "wall type disk radius 1\n").await;
    let edits = c.format(&uri).await;
    assert_eq!(edits[0]["newText"], "wall type disk\n  radius 1\n");
    let message = c.message().await;
    assert!(
        message.starts_with(&format!(
            "walls: {}:2:1: unknown field `indent`",
            config.display()
        )),
        "{message}"
    );
    assert!(
        message.ends_with("; formatting with the default options"),
        "{message}"
    );
}

#[tokio::test]
async fn hover_and_diagnostics_agree_on_lines_with_lone_carriage_returns() {
    let mut c = Client::start(json!({})).await;
    // pkdgrav reads `\r` as a blank, editors (and LSP) as a line end: lines 0 to 2.
    let text = "wall type disk\r  radius -1\r\n  epsn 2 k_n 1e5\n";
    let published = c.open(text).await;
    let ranges: Vec<_> = published["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| (d["code"].as_str().unwrap().to_string(), d["range"].clone()))
        .collect();
    let range = |line: u32, start: u32, end: u32| json!({"start": {"line": line, "character": start}, "end": {"line": line, "character": end}});
    // The lone carriage return itself (S006: a terminal would write over the line).
    let carriage_return =
        json!({"start": {"line": 0, "character": 14}, "end": {"line": 1, "character": 0}});
    assert_eq!(
        ranges,
        [
            ("S006".into(), carriage_return),
            ("C107".into(), range(1, 9, 11)),
            ("C114".into(), range(2, 7, 8))
        ]
    );
    let ranges = &ranges[1..];
    // A hover where each diagnostic starts is about that diagnostic's statement.
    for (_, r) in ranges {
        let hover = c
            .request(
                "textDocument/hover",
                json!({"textDocument": {"uri": URI}, "position": r["start"]}),
            )
            .await;
        let line = r["start"]["line"].as_u64().unwrap() as u32;
        assert_eq!(
            hover["range"],
            range(line, 2, r["end"]["character"].as_u64().unwrap() as u32)
        );
    }
    // The folds count the same lines.
    let folds = c
        .request(
            "textDocument/foldingRange",
            json!({"textDocument": {"uri": URI}}),
        )
        .await;
    assert_eq!(folds[0]["startLine"], 0);
    assert_eq!(folds[0]["endLine"], 2);
}

/// A folder with `walls.toml` holding `settings`, and the `file:` URI of `name` in it.
fn project(settings: &str, name: &str) -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("walls.toml"), settings).unwrap();
    let uri = format!("file://{}/{name}", dir.path().display());
    (dir, uri)
}

/// A plane's `radius` (the C201 warning) and a misspelt keyword (the S101 error).
const WARNING_AND_ERROR: &str = "wall type plane\n  radius 2\n  raduis 1\n";

/// Two walls: the C209 warning with `maxWalls` 1; in HSDEM, the M003 errors (both walls
/// leave `epsn` and `epst` at 99: one error for each coefficient).
const TWO_WALLS: &str = "wall type disk radius 1\nwall type plane\n";

#[tokio::test]
async fn the_settings_ignores_hide_warnings_but_never_errors() {
    let mut c = Client::start(json!({})).await;
    assert_eq!(codes(&c.open(WARNING_AND_ERROR).await), ["C201", "S101"]);
    let (dir, uri) = project(
        "[lint]\nmax-walls = 1\nignore = [\"ignored-by-type\", \"S101\", \"C304\"]\n\n[lint.per-file-ignores]\n\"old/*.walls\" = [\"C209\"]\n",
        "scene.walls",
    );
    assert_eq!(codes(&c.open_at(&uri, WARNING_AND_ERROR).await), ["S101"]);
    // Nor are the fixes of ignored diagnostics offered: the error's fix only (a disk's
    // `open-angle`, the C201 warning, and a mass without an assembly, the C304 error).
    let fixable = "wall type disk\n  open-angle 2\n  mass 1\n";
    assert_eq!(codes(&c.change(&uri, 2, fixable).await), ["C304"]);
    let actions = c.actions(&uri, (0, 0), (9, 0)).await;
    assert_eq!(titles(&actions), ["add `assembly 0` after the mass (C304)"]);
    // Per-file ignores: only in the files their glob matches.
    assert_eq!(codes(&c.change(&uri, 3, TWO_WALLS).await), ["C209"]);
    let old = format!("file://{}/old/a.walls", dir.path().display());
    assert!(codes(&c.open_at(&old, TWO_WALLS).await).is_empty());
}

#[tokio::test]
async fn the_settings_file_wins_over_the_editor_where_it_says_something() {
    let mut c = Client::start(json!({"mode": "ssdem", "maxWalls": 1})).await;
    let (dir, uri) = project("[lint]\nmode = \"hsdem\"\n", "scene.walls");
    // hsdem from the file, and the editor's maxWalls, which the file does not set.
    let published = c.open_at(&uri, TWO_WALLS).await;
    assert_eq!(codes(&published), ["M003", "M003", "C209"]);
    // A saved change to the settings file is seen at the next check.
    std::fs::write(dir.path().join("walls.toml"), "[lint]\nmax-walls = 2\n").unwrap();
    let published = c.change(&uri, 2, TWO_WALLS).await;
    assert!(codes(&published).is_empty(), "{published}");
    // And when the editor's settings change, the file still wins where it speaks.
    c.notify(
        "workspace/didChangeConfiguration",
        json!({"settings": {"walls": {"mode": "hsdem", "maxWalls": 1}}}),
    )
    .await;
    let published = c.diagnostics().await;
    assert_eq!(codes(&published), ["M003", "M003"]);
}

#[tokio::test]
async fn a_broken_settings_file_is_named_and_the_editor_settings_apply() {
    let mut c = Client::start(json!({"maxWalls": 1})).await;
    let (dir, uri) = project("[lint]\nmode = \"hsdem\"\n  mdoe = 1\n", "scene.walls");
    let published = c.open_at(&uri, TWO_WALLS).await;
    let settings = std::fs::canonicalize(dir.path().join("walls.toml")).unwrap();
    let d = &published["diagnostics"][0];
    assert_eq!(
        d["message"],
        format!(
            "{}:3:3: unknown field `mdoe`, expected one of `mode`, `max-walls`, `min-radius`, `dt`, `deny-warnings`, `ignore`, `per-file-ignores`, `include`, `exclude`\n\
             this file is checked with the editor's settings instead",
            settings.display()
        )
    );
    assert_eq!(d["severity"], 1);
    assert_eq!(
        d["range"],
        json!({"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 0}})
    );
    let related = &d["relatedInformation"][0]["location"];
    assert_eq!(related["uri"], format!("file://{}", settings.display()));
    assert_eq!(
        related["range"]["start"],
        json!({"line": 2, "character": 2})
    );
    // The rest: ssdem and maxWalls 1, the editor's.
    assert_eq!(d.get("code"), None);
    assert_eq!(codes(&published), ["-", "C209"]);
    // Fixed and saved: the file applies, and the diagnostic is gone.
    std::fs::write(&settings, "[lint]\nmode = \"hsdem\"\n").unwrap();
    let published = c.change(&uri, 2, TWO_WALLS).await;
    assert_eq!(codes(&published), ["M003", "M003", "C209"]);
}

#[tokio::test]
async fn an_untitled_document_takes_the_workspace_folder_settings() {
    let (dir, _) = project(
        "[lint]\nignore = [\"C201\"]\n[lint.per-file-ignores]\n\"*\" = [\"C209\"]\n",
        "",
    );
    let folder = format!("file://{}", dir.path().display());
    let mut c = Client::start_in(json!({"maxWalls": 1}), Some(&folder)).await;
    // `ignore` applies; per-file ignores do not, with no file to match.
    let published = c.open_at("untitled:Untitled-1", WARNING_AND_ERROR).await;
    assert_eq!(codes(&published), ["S101"]);
    let published = c.open_at("untitled:Untitled-2", TWO_WALLS).await;
    assert_eq!(codes(&published), ["C209"]);
    // Without a workspace folder, no settings file.
    let mut c = Client::start(json!({})).await;
    let published = c.open_at("untitled:Untitled-1", WARNING_AND_ERROR).await;
    assert_eq!(codes(&published), ["C201", "S101"]);
}

#[tokio::test]
async fn without_a_settings_file_the_editor_settings_alone_apply() {
    let dir = tempfile::tempdir().unwrap();
    let uri = format!("file://{}/scene.walls", dir.path().display());
    let mut c = Client::start(json!({"mode": "hsdem", "maxWalls": 1})).await;
    let published = c.open_at(&uri, TWO_WALLS).await;
    assert_eq!(codes(&published), ["M003", "M003", "C209"]);
    let published = c.open_at(&uri, WARNING_AND_ERROR).await;
    assert_eq!(codes(&published), ["M003", "M003", "C201", "S101"]);
}

#[tokio::test]
async fn control_characters_are_warnings_with_a_fix_only_between_words() {
    let mut c = Client::start(json!({})).await;
    // OSC 52 (set the clipboard) in a comment, a vertical tab between words.
    let text = "# \u{1b}]52;c;aGk=\u{7}\nwall type\u{b}plane # \u{202e}x\n";
    let published = c.open(text).await;
    let found: Vec<_> = published["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| {
            let r = &d["range"];
            (
                d["code"].as_str().unwrap().to_string(),
                d["severity"].as_u64().unwrap(),
                [
                    &r["start"]["line"],
                    &r["start"]["character"],
                    &r["end"]["character"],
                ]
                .map(|v| v.as_u64().unwrap()),
                d["message"]
                    .as_str()
                    .unwrap()
                    .lines()
                    .next()
                    .unwrap()
                    .to_string(),
            )
        })
        .collect();
    let warning = |at: [u64; 3], message: &str| ("S006".to_string(), 2, at, message.to_string());
    assert_eq!(
        found,
        [
            warning([0, 2, 3], "control character `\\x1b` in a comment"),
            warning([0, 13, 14], "control character `\\x07` in a comment"),
            warning([1, 9, 10], "control character `\\x0b` between words"),
            warning(
                [1, 18, 19],
                "bidirectional control `\\u{202e}` in a comment"
            ),
        ]
    );
    assert_eq!(
        titles(&c.actions(URI, (1, 9), (1, 10)).await),
        ["replace with a space (S006)", "Fix all safe problems (1)"]
    );
    assert_eq!(
        titles(&c.actions(URI, (0, 2), (0, 3)).await),
        ["Fix all safe problems (1)"]
    );
}

/// The whole of a document of `lines` lines, as an LSP range.
fn everything(lines: usize) -> Value {
    json!({"start": {"line": 0, "character": 0}, "end": {"line": lines, "character": 0}})
}

#[tokio::test]
async fn published_diagnostics_are_bounded_errors_first() {
    // 1,500 warnings (C202 on each `radius` but the last, C201 on the last), then an
    // error.
    let text = format!(
        "wall type plane\n{}  raduis 1\n",
        "  radius 1\n".repeat(1500)
    );
    let mut c = Client::start(json!({})).await;
    let published = c.open(&text).await;
    let d = published["diagnostics"].as_array().unwrap();
    assert_eq!(d.len(), 1001);
    // The error at the end is in, in its place.
    assert_eq!(d[999]["code"], "S101");
    assert_eq!(d[999]["range"]["start"]["line"], 1501);
    let note = &d[1000];
    assert_eq!(
        note["message"],
        "501 more diagnostics are not shown: the editor gets 1000 of this file's 1501, \
         errors first; `walls-lint` lists them all"
    );
    assert_eq!(note["severity"], 3);
    // At the first one left out: the 1,000th warning, on line 1,000.
    assert_eq!(note["range"]["start"]["line"], 1000);
}

#[tokio::test]
async fn the_outline_is_bounded_and_shaped_to_fit() {
    let mut c = Client::start(json!({})).await;
    let doc = json!({"uri": URI});
    let outline = |n: usize| "wall type disk\n  radius 1\n".repeat(n);
    // 500 walls and their 1,000 statements: all of them.
    c.open(&outline(500)).await;
    let symbols = c
        .request("textDocument/documentSymbol", json!({"textDocument": doc}))
        .await;
    assert_eq!(symbols.as_array().unwrap().len(), 500);
    assert_eq!(symbols[0]["children"].as_array().unwrap().len(), 2);
    // 1,000 walls: the walls alone.
    c.change(URI, 2, &outline(1000)).await;
    let symbols = c
        .request("textDocument/documentSymbol", json!({"textDocument": doc}))
        .await;
    assert_eq!(symbols.as_array().unwrap().len(), 1000);
    assert_eq!(symbols[999]["name"], "wall 999: disk");
    assert_eq!(symbols[999]["children"], json!([]));
    // 30,000 walls: 300 runs of 100.
    c.change(URI, 3, &outline(30_000)).await;
    let symbols = c
        .request("textDocument/documentSymbol", json!({"textDocument": doc}))
        .await;
    let symbols = symbols.as_array().unwrap();
    assert_eq!(symbols.len(), 300);
    assert_eq!(symbols[1]["name"], "walls 100–199");
    assert_eq!(symbols[1]["kind"], 18);
    assert_eq!(symbols[1]["range"]["start"]["line"], 200);
    assert_eq!(symbols[1]["range"]["end"]["line"], 399);
}

#[tokio::test]
async fn tokens_folds_hints_and_fixes_are_bounded() {
    let mut c = Client::start(json!({})).await;
    let doc = json!({"uri": URI});
    // 60,004 tokens on two lines: the first 50,000.
    c.open(&format!(
        "wall type plane\n  origin{}\n",
        " 1".repeat(60_000)
    ))
    .await;
    let tokens = c
        .request(
            "textDocument/semanticTokens/full",
            json!({"textDocument": doc}),
        )
        .await;
    assert_eq!(tokens["data"].as_array().unwrap().len(), 5 * 50_000);
    // 6,000 blocks of two lines: 5,000 folds.
    let walls = "wall type disk\n  radius 1\n".repeat(6000);
    c.change(URI, 2, &walls).await;
    let folds = c
        .request("textDocument/foldingRange", json!({"textDocument": doc}))
        .await;
    assert_eq!(folds.as_array().unwrap().len(), 5000);
    // 2,000 walls that inherit a colour: 1,000 hints.
    let inheriting = format!("defaults\n  color 3\n{walls}");
    c.change(URI, 3, &inheriting).await;
    let hints = c
        .request(
            "textDocument/inlayHint",
            json!({"textDocument": doc, "range": everything(12_002)}),
        )
        .await;
    assert_eq!(hints.as_array().unwrap().len(), 1000);
    // 6,000 safe fixes (`radius` on a plane): 100 quick fixes, and one edit fixing all.
    let fixable = format!("wall type plane\n{}", "  radius 1\n".repeat(6000));
    c.change(URI, 4, &fixable).await;
    let actions = c.actions(URI, (0, 0), (6001, 0)).await;
    let actions = actions.as_array().unwrap();
    assert_eq!(actions.len(), 101);
    let all = &actions[100];
    assert_eq!(all["kind"], "source.fixAll");
    assert_eq!(all["edit"]["changes"][URI].as_array().unwrap().len(), 1);
    assert_eq!(
        all["edit"]["changes"][URI][0]["newText"],
        "wall type plane\n"
    );
}

#[cfg(unix)]
#[tokio::test]
async fn a_fifo_named_walls_toml_is_named_not_waited_on() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("walls.toml");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap();
    assert!(made.success());
    let uri = format!("file://{}/scene.walls", dir.path().display());
    let mut c = Client::start(json!({"maxWalls": 1})).await;
    let published = c.open_at(&uri, TWO_WALLS).await;
    let settings = std::fs::canonicalize(&fifo).unwrap();
    assert_eq!(
        published["diagnostics"][0]["message"],
        format!(
            "{}: is a fifo, not a settings file (a settings file found in a folder is a regular file)\n\
             this file is checked with the editor's settings instead",
            settings.display()
        )
    );
    assert_eq!(codes(&published), ["-", "C209"]);
}

#[tokio::test]
async fn par_files_are_checked_hovered_and_completed_for_the_build() {
    let dir = tempfile::tempdir().unwrap();
    let uri = |name: &str| format!("file://{}/{name}", dir.path().display());
    let mut c = Client::start(json!({})).await;
    // pkdgrav's reader: `!` is a syntax error, `dKN` no key of the build.
    let text = "achInFile = ss.ic\ndKN = 1e5 ! spring\niCohesionModel = 1\n";
    let published = c.open_at(&uri("run.par"), text).await;
    let found = codes(&published);
    assert!(
        found.contains(&"P001".to_string()) && found.contains(&"P003".to_string()),
        "{found:?}"
    );
    let d = published["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .find(|d| d["code"] == "P001")
        .unwrap();
    assert_eq!(
        d["range"],
        json!({"start": {"line": 1, "character": 10}, "end": {"line": 1, "character": 11}})
    );
    let hover = c
        .request(
            "textDocument/hover",
            json!({"textDocument": {"uri": uri("run.par")}, "position": {"line": 2, "character": 3}}),
        )
        .await;
    let shown = hover["contents"]["value"].as_str().unwrap();
    assert!(shown.starts_with("**`iCohesionModel`** (int"), "{shown}");
    assert!(shown.contains("Not registered by this build"), "{shown}");
    // With the settings' build, the cohesion keys are the build's.
    std::fs::write(
        dir.path().join("walls.toml"),
        "[run]\npkdgrav-build = \"DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT DEM_COHESION\"\n",
    )
    .unwrap();
    c.change(&uri("run.par"), 2, "iCoh").await;
    let items = c
        .request(
            "textDocument/completion",
            json!({"textDocument": {"uri": uri("run.par")}, "position": {"line": 0, "character": 4}}),
        )
        .await;
    let labels: Vec<&str> = items
        .as_array()
        .unwrap()
        .iter()
        .map(|i| i["label"].as_str().unwrap())
        .collect();
    assert_eq!(labels, ["iCohesionModel"]);
    // Its fixes: a comment indented (safe) moved to the first column, a duplicate's
    // overridden line deleted, both in "fix all".
    c.change(&uri("run.par"), 3, "  # note\nnSteps = 1\nnSteps = 2\n")
        .await;
    let actions = c.actions(&uri("run.par"), (0, 0), (2, 0)).await;
    assert_eq!(
        titles(&actions),
        [
            "move the comment to the first column (P001)",
            "delete the line pkdgrav overrides (P006)",
            "Fix all safe problems (2)"
        ]
    );
    let all = actions.as_array().unwrap().last().unwrap();
    let edits = all["edit"]["changes"][uri("run.par")].as_array().unwrap();
    assert_eq!(edits[0]["newText"], "# note\nnSteps = 2\n");
    // ssdraw.par is ssdraw's, neither a pkdgrav .par nor a walls file: nothing is
    // published for it (the next diagnostics are the walls file's opened after it).
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": uri("ssdraw.par"), "languageId": "walls", "version": 1, "text": "Camera position 1 2 3\n"}}),
    )
    .await;
    let published = c.open_at(&uri("w.walls"), "wall type plane\n").await;
    assert_eq!(published["uri"], uri("w.walls"));
}
