#!/usr/bin/env python3
# Fills the English plural forms of translations/ggstudio_en.ts (English is
# the source language: only "%n ..." texts need an entry there).
import re, sys, html
path = sys.argv[1]
text = open(path, encoding='utf-8').read()

def forms(source):
    if '(s)' in source:
        return source.replace('(s)', ''), source.replace('(s)', 's')
    m = re.search(r'%n (\w+)', source)
    if m and m.group(1).endswith('s'):
        word = m.group(1)
        return source.replace('%n ' + word, '%n ' + word[:-1], 1), source
    return source, source

def fill(match):
    block = match.group(0)
    if 'type="unfinished"' not in block:
        return block
    source = html.unescape(re.search(r'<source>(.*?)</source>', block, re.S).group(1))
    one, many = forms(source)
    esc = lambda s: html.escape(s, quote=False)
    translation = ('<translation>\n            <numerusform>%s</numerusform>\n'
                   '            <numerusform>%s</numerusform>\n        </translation>') % (esc(one), esc(many))
    return re.sub(r'<translation type="unfinished">.*?</translation>', translation, block, flags=re.S)

text = re.sub(r'<message numerus="yes">.*?</message>', fill, text, flags=re.S)
open(path, 'w', encoding='utf-8').write(text)
