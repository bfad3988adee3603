/* xmlio.c — libxml2 adapter: atomic output and checked parsing (xmlio.h). */
#include "io/xmlio.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <libxml/parser.h>

#include "core/error.h"

int xml_out_open(struct xml_out *o, const char *path)
{
    xmlOutputBufferPtr buf;
    size_t len = strlen(path) + 32;

    memset(o, 0, sizeof *o);
    o->path = path;
    o->tmp = sim_malloc(len);
    if (!o->tmp)
        return SIM_ERR_NOMEM;
    snprintf(o->tmp, len, "%s.tmp.%ld", path, (long)getpid());
    o->fp = fopen(o->tmp, "wb");
    if (!o->fp) {
        int rc = sim_error(SIM_ERR_IO, "%s: cannot create: %s", o->tmp,
                           strerror(errno));
        free(o->tmp);
        o->tmp = NULL;
        return rc;
    }
    /* The buffer only flushes into our FILE; we close it ourselves so that
     * a late write error (disk full) is seen by fclose() in commit. */
    buf = xmlOutputBufferCreateFile(o->fp, NULL);
    if (buf)
        o->w = xmlNewTextWriter(buf);
    if (!o->w) {
        if (buf)
            xmlOutputBufferClose(buf);
        xml_out_abort(o);
        return sim_error(SIM_ERR_EXTERNAL, "%s: libxml2 cannot create a "
                         "writer", path);
    }
    xml_out_check(o, xmlTextWriterSetIndent(o->w, 1));
    xml_out_check(o, xmlTextWriterSetIndentString(o->w, BAD_CAST "  "));
    xml_out_check(o, xmlTextWriterStartDocument(o->w, "1.0", NULL, NULL));
    return SIM_OK;
}

void xml_out_abort(struct xml_out *o)
{
    if (o->w)
        xmlFreeTextWriter(o->w);
    if (o->fp)
        fclose(o->fp);
    if (o->tmp)
        unlink(o->tmp);
    free(o->tmp);
    o->w = NULL;
    o->fp = NULL;
    o->tmp = NULL;
}

int xml_out_commit(struct xml_out *o)
{
    int rc = SIM_OK;

    xml_out_check(o, xmlTextWriterEndDocument(o->w));
    xml_out_check(o, xmlTextWriterFlush(o->w));
    xmlFreeTextWriter(o->w);
    o->w = NULL;
    if (o->failed || fflush(o->fp) != 0 || ferror(o->fp)) {
        rc = sim_error(SIM_ERR_IO, "%s: write failed: %s", o->path,
                       errno ? strerror(errno) : "libxml2 writer error");
        goto fail;
    }
    if (fclose(o->fp) != 0) {
        o->fp = NULL;
        rc = sim_error(SIM_ERR_IO, "%s: write failed: %s", o->path,
                       strerror(errno));
        goto fail;
    }
    o->fp = NULL;
    if (rename(o->tmp, o->path) != 0) {
        rc = sim_error(SIM_ERR_IO, "%s: cannot rename %s onto it: %s",
                       o->path, o->tmp, strerror(errno));
        goto fail;
    }
    free(o->tmp);
    o->tmp = NULL;
    return SIM_OK;
fail:
    xml_out_abort(o);
    return rc;
}

/* Our files never declare a document type; refusing one keeps entity
 * expansion (a "billion laughs" file) out of a parser that must accept
 * huge text nodes. */
static void refuse_dtd(void *ctx, const xmlChar *name, const xmlChar *ext,
                       const xmlChar *sys)
{
    xmlParserCtxtPtr c = ctx;
    (void)name;
    (void)ext;
    (void)sys;
    c->_private = (void *)1;
    xmlStopParser(c);
}

int xml_in_read(const char *path, xmlDocPtr *doc)
{
    xmlParserCtxtPtr ctx;
    const xmlError *e;
    FILE *fp;

    *doc = NULL;
    /* Say "cannot open" rather than libxml2's less direct message. */
    fp = fopen(path, "rb");
    if (!fp)
        return sim_error(SIM_ERR_IO, "%s: cannot open: %s", path,
                         strerror(errno));
    fclose(fp);
    ctx = xmlNewParserCtxt();
    if (!ctx)
        return sim_error(SIM_ERR_NOMEM, "%s: libxml2 cannot create a parser",
                         path);
    ctx->sax->internalSubset = refuse_dtd;
    ctx->_private = NULL;
    *doc = xmlCtxtReadFile(ctx, path, NULL,
                           XML_PARSE_HUGE | XML_PARSE_NONET |
                               XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    e = xmlCtxtGetLastError(ctx);
    if (ctx->_private) {
        xmlFreeParserCtxt(ctx);
        if (*doc)
            xmlFreeDoc(*doc);
        *doc = NULL;
        return sim_error(SIM_ERR_IO, "%s: document type declarations "
                         "(<!DOCTYPE>) are not accepted", path);
    }
    if (*doc && (!e || e->level < XML_ERR_ERROR)) {
        xmlFreeParserCtxt(ctx);
        return SIM_OK;
    }
    {
        char msg[256] = "not well-formed XML";
        int line = e ? e->line : 0;
        if (e && e->message) {
            snprintf(msg, sizeof msg, "%s", e->message);
            msg[strcspn(msg, "\n")] = '\0';
        }
        xmlFreeParserCtxt(ctx);
        if (*doc)
            xmlFreeDoc(*doc);
        *doc = NULL;
        return sim_error(SIM_ERR_IO, "%s: line %d: not valid XML (truncated "
                         "or corrupted?): %s", path, line, msg);
    }
}

xmlNodePtr xml_child(xmlNodePtr parent, const char *name)
{
    for (xmlNodePtr c = parent ? parent->children : NULL; c; c = c->next)
        if (c->type == XML_ELEMENT_NODE &&
            strcmp((const char *)c->name, name) == 0)
            return c;
    return NULL;
}

int xml_attr(xmlNodePtr node, const char *name, char *buf, size_t n)
{
    xmlChar *v = xmlGetProp(node, BAD_CAST name);
    int rc = 1;

    if (!v)
        return 0;
    if (strlen((const char *)v) >= n)
        rc = -1;
    else
        strcpy(buf, (const char *)v);
    xmlFree(v);
    return rc;
}
