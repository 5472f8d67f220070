//! The walls language server.
//!
//! A thin adapter: it keeps the open documents (each checked by `walls-ide`), converts
//! LSP positions (UTF-16) to byte offsets and back ([`position`]), and maps the plain
//! answers of `walls-ide`'s feature functions into LSP values:
//! - diagnostics come from the syntax check and the checker, with the `[lint]` settings
//!   found for the document (`walls.toml`, …, above its file; the workspace folder's for
//!   a document that is not a file): the values the file sets win over the editor's
//!   `mode` and `maxWalls`, its `ignore` and `per-file-ignores` hide warnings as in
//!   `walls-lint`, and an unusable settings file is one error diagnostic naming it (the
//!   editor's settings apply meanwhile). They are found again at every check
//!   ([`settings`]), so a saved change to them shows at the next edit;
//! - hovers show the keyword's documentation and its effective value;
//! - formatting and range formatting use `walls-format` (options from the settings
//!   file found for the document, as `walls-fmt` finds them: `walls.toml`'s `[format]`
//!   or `.walls-fmt.toml`; an unusable one is named in a message to the user, and the
//!   defaults are used);
//! - code actions apply the checker's fixes, plus a "fix all safe" action;
//! - the outline shows walls and defaults blocks;
//! - folding covers blocks;
//! - completion knows the context (type names after `type`, the wall type's tokens
//!   first), semantic tokens colour the file, inlay hints show inherited, scaled and
//!   derived values, and go to definition leads from a value to the token that set it;
//! - the custom request `walls/explain` (`{"query": "S101"}`, a code's id or name, or a
//!   keyword) answers the explanation `walls-lint --explain` prints, in Markdown, or
//!   `null`, so that editors can explain the code of a diagnostic.
//!
//! Settings (initialization options, or the `walls` section of the configuration) with a
//! bad value or an unknown key are named in one message to the user; the rest apply.
//!
//! The stream is framed by [`serve`] before tower-lsp's server sees it, so that a bad
//! message is answered and skipped, never the end of the server, and a message too long
//! or of too many JSON values is refused before it costs memory.
//!
//! Every answer has a bound whatever the document (the `MAX_…` constants of the
//! features: 1,000 diagnostics published, an outline of 2,000 entries shaped to fit,
//! 50,000 semantic tokens, …; docs/editors.md, "Limits").
//!
//! Edits are applied under one lock, and a document's diagnostics are published with
//! its version, and only if no newer version has arrived meanwhile.

mod document;
mod entry;
mod features;
pub mod position;
mod settings;
mod transport;

use document::{Document, ParDocument, is_par};
use settings::Check;
use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Mutex;
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::*;
use tower_lsp_server::{Client, LanguageServer, LspService};
use walls_format::FormatOptions;
use walls_model::{ContactModel, Options};

/// The server's state: the open documents and the checker's options.
pub struct Backend {
    client: Client,
    state: Mutex<State>,
}

#[derive(Default)]
struct State {
    documents: HashMap<Uri, Document>,
    /// The open pkdgrav `.par` files ([`document::is_par`]).
    par_documents: HashMap<Uri, ParDocument>,
    /// The editor's options (what a settings file does not set).
    options: Options,
    /// The (first) workspace folder: where the settings of a document that is not a file
    /// are looked for.
    folder: Option<PathBuf>,
    /// What was wrong with the initialization options, told once initialized.
    init_problems: Vec<String>,
}

/// The service and the socket its notifications to the client go through.
pub fn service() -> (LspService<Backend>, tower_lsp_server::ClientSocket) {
    LspService::build(|client| Backend {
        client,
        state: Mutex::new(State::default()),
    })
    .custom_method("walls/explain", Backend::explain)
    .finish()
}

/// The parameters of `walls/explain`.
#[derive(Debug, serde::Deserialize)]
pub struct ExplainParams {
    /// A diagnostic code's id (`S101`) or name (`unknown-word`), or a keyword.
    pub query: String,
}

pub use entry::{Args, entry};
pub use transport::serve;

/// Serves LSP over standard input and output until the client exits (or closes the
/// input). Does not wait for a read of standard input still under way.
pub fn serve_stdio() -> std::io::Result<()> {
    let runtime = tokio::runtime::Runtime::new()?;
    runtime.block_on(serve(tokio::io::stdin(), tokio::io::stdout()));
    // Standard input is read by a blocking thread that nothing can stop: a client that
    // keeps it open after `exit` must not keep the server alive.
    runtime.shutdown_background();
    Ok(())
}

/// Reads `{"mode": "hsdem", "maxWalls": 30}` (initialization options, or the `walls`
/// section of the settings) into the checker's options. A bad value keeps the option as
/// it was, and an unknown key is ignored; each gives a sentence for the user, naming the
/// key and the value.
fn options_from(value: &serde_json::Value, mut options: Options) -> (Options, Vec<String>) {
    let mut problems = Vec::new();
    let Some(settings) = value.as_object() else {
        if !value.is_null() {
            problems.push(format!("the settings are {value}, not an object: ignored"));
        }
        return (options, problems);
    };
    for (key, value) in settings {
        match key.as_str() {
            "mode" => match value.as_str() {
                Some("hsdem") => options.mode = ContactModel::Hsdem,
                Some("ssdem") => options.mode = ContactModel::Ssdem,
                _ => problems.push(format!(
                    "setting `mode` is {value}, not \"ssdem\" or \"hsdem\": keeping \"{}\"",
                    match options.mode {
                        ContactModel::Ssdem => "ssdem",
                        ContactModel::Hsdem => "hsdem",
                    }
                )),
            },
            "maxWalls" => match value.as_u64().and_then(|n| usize::try_from(n).ok()) {
                Some(n) if n >= 1 => options.max_walls = n,
                _ => problems.push(format!(
                    "setting `maxWalls` is {value}, not a whole number of at least 1: keeping {}",
                    options.max_walls
                )),
            },
            // The VS Code client's own settings, sent with the section.
            "server" | "trace" => {}
            _ => problems.push(format!(
                "unknown setting `{key}` (= {value}) ignored; the settings are `mode` and `maxWalls`"
            )),
        }
    }
    (options, problems)
}

/// The message that tells the user about bad settings, if there are any.
fn settings_message(problems: &[String]) -> Option<String> {
    (!problems.is_empty()).then(|| format!("walls: {}.", problems.join("; ")))
}

impl Backend {
    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        // A panic in another handler must not take the server down with it.
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Publishes the diagnostics of `uri` at `version`, unless a newer version came.
    async fn publish(&self, uri: Uri, version: i32) {
        let diagnostics = {
            let state = self.lock();
            match (state.documents.get(&uri), state.par_documents.get(&uri)) {
                (Some(doc), _) if doc.version == version => features::diagnostics(&uri, doc),
                (_, Some(doc)) if doc.version == version => features::par_diagnostics(&uri, doc),
                _ => return,
            }
        };
        self.client
            .publish_diagnostics(uri, diagnostics, Some(version))
            .await;
    }

    /// `walls/explain`: what a code (or keyword) means, in Markdown, as
    /// `walls-lint --explain` prints it; `null` for anything else.
    async fn explain(&self, params: ExplainParams) -> Result<Option<String>> {
        Ok(walls_ide::explain(&params.query))
    }

    /// The formatting options of `uri`'s project; the defaults, and a message to the
    /// user naming the file and what is wrong, if its settings file is unusable.
    async fn format_options(&self, uri: &Uri) -> FormatOptions {
        let folder = self.lock().folder.clone();
        match settings::format_options(uri, folder.as_deref()) {
            Ok(options) => options,
            Err(e) => {
                let message = format!("walls: {e}; formatting with the default options");
                self.client
                    .show_message(MessageType::WARNING, message)
                    .await;
                FormatOptions::default()
            }
        }
    }

    /// Checks `text` as the document at `uri`, with the settings found for it now.
    fn document(state: &State, uri: &Uri, version: i32, text: String) -> Document {
        let check = Check::find(uri, state.folder.as_deref(), &state.options);
        Document::new(version, text, check)
    }

    /// Checks `text` as the document at `uri` in its language (a `.par` file or a walls
    /// file) and keeps it, in place of what the document was.
    fn keep(state: &mut State, uri: Uri, version: i32, text: String) {
        // ssdraw's parameter file (a `*.par` association sends it) is neither language:
        // no document, no diagnostics.
        let path = uri.path().as_str();
        if path
            .rsplit('/')
            .next()
            .is_some_and(walls_par::is_ssdraw_par)
        {
            return;
        }
        if is_par(&uri) {
            let check = Check::find(&uri, state.folder.as_deref(), &state.options);
            state
                .par_documents
                .insert(uri, ParDocument::new(version, text, check));
        } else {
            let document = Self::document(state, &uri, version, text);
            state.documents.insert(uri, document);
        }
    }

    fn with_par_document<T>(&self, uri: &Uri, f: impl FnOnce(&ParDocument) -> T) -> Option<T> {
        self.lock().par_documents.get(uri).map(f)
    }

    fn with_document<T>(&self, uri: &Uri, f: impl FnOnce(&Document) -> T) -> Option<T> {
        self.lock().documents.get(uri).map(f)
    }
}

impl LanguageServer for Backend {
    async fn initialize(&self, params: InitializeParams) -> Result<InitializeResult> {
        {
            let mut state = self.lock();
            if let Some(init) = &params.initialization_options {
                (state.options, state.init_problems) = options_from(init, state.options.clone());
            }
            #[allow(deprecated)] // `root_uri`: what clients without workspace folders send.
            let root = params.root_uri.as_ref();
            let folders = params.workspace_folders.as_deref().unwrap_or_default();
            state.folder = folders
                .first()
                .map(|f| &f.uri)
                .or(root)
                .and_then(settings::file_path);
        }
        Ok(InitializeResult {
            capabilities: ServerCapabilities {
                text_document_sync: Some(TextDocumentSyncCapability::Kind(
                    TextDocumentSyncKind::FULL,
                )),
                hover_provider: Some(HoverProviderCapability::Simple(true)),
                document_formatting_provider: Some(OneOf::Left(true)),
                document_range_formatting_provider: Some(OneOf::Left(true)),
                code_action_provider: Some(CodeActionProviderCapability::Simple(true)),
                document_symbol_provider: Some(OneOf::Left(true)),
                folding_range_provider: Some(FoldingRangeProviderCapability::Simple(true)),
                completion_provider: Some(CompletionOptions {
                    trigger_characters: Some(vec![" ".into()]),
                    ..CompletionOptions::default()
                }),
                semantic_tokens_provider: Some(
                    SemanticTokensOptions {
                        legend: SemanticTokensLegend {
                            token_types: features::TOKEN_TYPES.to_vec(),
                            token_modifiers: Vec::new(),
                        },
                        full: Some(SemanticTokensFullOptions::Bool(true)),
                        range: Some(true),
                        ..SemanticTokensOptions::default()
                    }
                    .into(),
                ),
                inlay_hint_provider: Some(OneOf::Left(true)),
                definition_provider: Some(OneOf::Left(true)),
                ..ServerCapabilities::default()
            },
            server_info: Some(ServerInfo {
                name: "walls-lsp".into(),
                version: Some(env!("CARGO_PKG_VERSION").into()),
            }),
            ..InitializeResult::default()
        })
    }

    async fn initialized(&self, _: InitializedParams) {
        let problems = std::mem::take(&mut self.lock().init_problems);
        if let Some(message) = settings_message(&problems) {
            self.client
                .show_message(MessageType::WARNING, message)
                .await;
        }
    }

    async fn shutdown(&self) -> Result<()> {
        Ok(())
    }

    async fn did_open(&self, params: DidOpenTextDocumentParams) {
        let doc = params.text_document;
        Self::keep(&mut self.lock(), doc.uri.clone(), doc.version, doc.text);
        self.publish(doc.uri, doc.version).await;
    }

    async fn did_change(&self, params: DidChangeTextDocumentParams) {
        let uri = params.text_document.uri;
        let version = params.text_document.version;
        // Full synchronisation: the last change holds the whole text.
        let Some(change) = params.content_changes.into_iter().last() else {
            return;
        };
        {
            let mut state = self.lock();
            let newer = |v: i32| v > version;
            if state.documents.get(&uri).is_some_and(|d| newer(d.version))
                || state
                    .par_documents
                    .get(&uri)
                    .is_some_and(|d| newer(d.version))
            {
                return;
            }
            Self::keep(&mut state, uri.clone(), version, change.text);
        }
        self.publish(uri, version).await;
    }

    async fn did_close(&self, params: DidCloseTextDocumentParams) {
        let uri = params.text_document.uri;
        {
            let mut state = self.lock();
            state.documents.remove(&uri);
            state.par_documents.remove(&uri);
        }
        self.client.publish_diagnostics(uri, Vec::new(), None).await;
    }

    async fn did_change_configuration(&self, params: DidChangeConfigurationParams) {
        let section = params
            .settings
            .get("walls")
            .unwrap_or(&params.settings)
            .clone();
        let (versions, problems): (Vec<(Uri, i32)>, _) = {
            let mut state = self.lock();
            let (options, problems) = options_from(&section, state.options.clone());
            state.options = options;
            // Every open document is checked again with the new options.
            let documents = std::mem::take(&mut state.documents);
            let mut versions = Vec::with_capacity(documents.len());
            for (uri, doc) in documents {
                let doc = Self::document(&state, &uri, doc.version, doc.text().to_string());
                versions.push((uri.clone(), doc.version));
                state.documents.insert(uri, doc);
            }
            for (uri, doc) in std::mem::take(&mut state.par_documents) {
                versions.push((uri.clone(), doc.version));
                Self::keep(&mut state, uri, doc.version, doc.text().to_string());
            }
            (versions, problems)
        };
        if let Some(message) = settings_message(&problems) {
            self.client
                .show_message(MessageType::WARNING, message)
                .await;
        }
        for (uri, version) in versions {
            self.publish(uri, version).await;
        }
    }

    async fn hover(&self, params: HoverParams) -> Result<Option<Hover>> {
        let p = params.text_document_position_params;
        let uri = &p.text_document.uri;
        if let Some(hover) = self.with_par_document(uri, |doc| features::par_hover(doc, p.position))
        {
            return Ok(hover);
        }
        Ok(self
            .with_document(uri, |doc| features::hover(doc, p.position))
            .flatten())
    }

    async fn formatting(&self, params: DocumentFormattingParams) -> Result<Option<Vec<TextEdit>>> {
        let uri = params.text_document.uri;
        let options = self.format_options(&uri).await;
        Ok(self
            .with_document(&uri, |doc| features::format(doc, &options))
            .flatten())
    }

    async fn range_formatting(
        &self,
        params: DocumentRangeFormattingParams,
    ) -> Result<Option<Vec<TextEdit>>> {
        let uri = params.text_document.uri;
        let options = self.format_options(&uri).await;
        Ok(self
            .with_document(&uri, |doc| {
                features::format_range(doc, params.range, &options)
            })
            .flatten())
    }

    async fn code_action(&self, params: CodeActionParams) -> Result<Option<CodeActionResponse>> {
        let uri = params.text_document.uri.clone();
        let range = params.range;
        Ok(self
            .with_par_document(&uri, |doc| features::par_code_actions(&uri, doc, range))
            .or_else(|| self.with_document(&uri, |doc| features::code_actions(&uri, doc, range)))
            .filter(|actions| !actions.is_empty()))
    }

    async fn document_symbol(
        &self,
        params: DocumentSymbolParams,
    ) -> Result<Option<DocumentSymbolResponse>> {
        Ok(self.with_document(&params.text_document.uri, |doc| {
            DocumentSymbolResponse::Nested(features::symbols(doc))
        }))
    }

    async fn completion(&self, params: CompletionParams) -> Result<Option<CompletionResponse>> {
        let p = params.text_document_position;
        let uri = &p.text_document.uri;
        if let Some(items) =
            self.with_par_document(uri, |doc| features::par_completion(doc, p.position))
        {
            return Ok(Some(CompletionResponse::Array(items)));
        }
        Ok(self
            .with_document(uri, |doc| features::completion(doc, p.position))
            .map(CompletionResponse::Array))
    }

    async fn semantic_tokens_full(
        &self,
        params: SemanticTokensParams,
    ) -> Result<Option<SemanticTokensResult>> {
        Ok(self.with_document(&params.text_document.uri, |doc| {
            SemanticTokens {
                result_id: None,
                data: features::semantic_tokens(doc, None),
            }
            .into()
        }))
    }

    async fn semantic_tokens_range(
        &self,
        params: SemanticTokensRangeParams,
    ) -> Result<Option<SemanticTokensRangeResult>> {
        Ok(self.with_document(&params.text_document.uri, |doc| {
            SemanticTokens {
                result_id: None,
                data: features::semantic_tokens(doc, Some(params.range)),
            }
            .into()
        }))
    }

    async fn inlay_hint(&self, params: InlayHintParams) -> Result<Option<Vec<InlayHint>>> {
        Ok(self.with_document(&params.text_document.uri, |doc| {
            features::inlay_hints(doc, params.range)
        }))
    }

    async fn goto_definition(
        &self,
        params: GotoDefinitionParams,
    ) -> Result<Option<GotoDefinitionResponse>> {
        let p = params.text_document_position_params;
        let uri = p.text_document.uri;
        Ok(self
            .with_document(&uri, |doc| features::definition(doc, &uri, p.position))
            .filter(|l| !l.is_empty())
            .map(GotoDefinitionResponse::Array))
    }

    async fn folding_range(&self, params: FoldingRangeParams) -> Result<Option<Vec<FoldingRange>>> {
        Ok(self.with_document(&params.text_document.uri, features::folding))
    }
}
